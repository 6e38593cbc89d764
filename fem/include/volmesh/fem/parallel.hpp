#pragma once
// The ranks of a run and the PETSc backend's life cycle, without MPI or PETSc headers (they
// stay in the backend's .cpp files). A build without PETSc has one rank and these calls do
// nothing.
//
// PETSc (and MPI) start when the program runs under mpirun, or at the first PETSc solve of a
// serial run, and stop when the Session ends. PETSc's own options (-ksp_*, -pc_*,
// -log_view, ...) are taken off the command line by the Session and handed to PETSc's
// options database, so that they override the backend's defaults.
#include <cstddef>
#include <string>
#include <vector>

namespace volmesh::fem {

// Whether this build has the PETSc backend (with hypre).
bool petsc_built();
// One line for --version: the linear solver backends of this build.
std::string backend_summary();

class Session {
 public:
  // Removes PETSc's options from argv (argc shrinks): a word "-name" with a letter after the
  // single dash and at least two characters (volmesh's own short options are one letter),
  // with the next word as its value unless that starts with '-' and a letter.
  Session(int& argc, char** argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

// PETSc's options given on the command line ("-ksp_rtol 1e-8 ..."), for a re-launch.
const std::vector<std::string>& petsc_arguments();

// Starts PETSc now if this build has it and it has not started (collective under mpirun).
void start_petsc();
bool petsc_started();

// Whether mpirun started this run (even with one rank): the solves are then distributed.
bool distributed_run();

// This process's rank and the number of ranks (0 and 1 without MPI).
int rank();
int ranks();

// Collectives over all ranks (each a no-op on one rank); every rank must call them in the
// same order.
void sum_over_ranks(double* values, std::size_t count);  // in place
double max_over_ranks(double value);
// Every rank's `mine`, concatenated in rank order, on every rank.
std::vector<double> gather_to_all(const double* mine, std::size_t count);
// Rank 0's bytes on every rank.
void broadcast(std::vector<char>& bytes);
// Every rank's bytes on every rank, in rank order.
std::vector<std::vector<char>> gather_bytes_to_all(const std::vector<char>& mine);
// Waits for all ranks (the parallel writers' pieces before the summary file).
void barrier();

// Agrees on a stage's outcome: `error` is this rank's failure ("" for none). When any rank
// failed, every rank throws InputError with the lowest failing rank's message, so that all
// exit together and rank 0 prints it; a rank-0-only stage (meshing) ends with this so that
// the others do not wait for a broadcast that never comes. Ranks that arrive early sleep in
// short steps rather than poll a core, so rank 0's serial stages keep a core to themselves.
void agree(const std::string& error);

}  // namespace volmesh::fem
