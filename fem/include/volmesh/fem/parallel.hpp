#pragma once
// The ranks of a run and the PETSc backend's life cycle, without MPI or PETSc headers (they
// stay in the backend's .cpp files). A build without PETSc has one rank and these calls do
// nothing.
//
// PETSc (and MPI) start when the program runs under mpirun, or at the first PETSc solve of a
// serial run, and stop when the Session ends. PETSc's own options (-ksp_*, -pc_*,
// -log_view, ...) are taken off the command line by the Session and handed to PETSc's
// options database, so that they override the backend's defaults. They go at the end of the
// command line, after the subcommand's own arguments, or after "--".
#include <cstddef>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace volmesh::fem {

// Whether this build has the PETSc backend (with hypre).
bool petsc_built();
// One line for --version: the linear solver backends of this build.
std::string backend_summary();

class Session {
 public:
  // Takes PETSc's options off argv (argc shrinks). A PETSc option is a word "-name" whose
  // name is letters, digits and underscores with at least one underscore (-ksp_rtol,
  // -pc_type, -log_view; volmesh's own options are "--name" or one letter). From the first
  // of them to the end, every word is PETSc's (an option or its value), and so is every word
  // after "--" (which goes too). An option of volmesh's own among them is not taken:
  // petsc_options_misplaced() says so.
  Session(int& argc, char** argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

// PETSc's options given on the command line ("-ksp_rtol 1e-8 ..."), for a re-launch.
const std::vector<std::string>& petsc_arguments();
// One line when an option of volmesh's own follows a PETSc option (a usage error, exit 2);
// empty otherwise.
const std::string& petsc_options_misplaced();

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
// Values from every rank to every rank: to[r] goes to rank r; returns from[r], what rank r
// sent this one (one all-to-all of the counts, one of the values).
std::vector<std::vector<double>> exchange(const std::vector<std::vector<double>>& to);
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
// A failed rank whose partners do not arrive within kStrandedSeconds (they wait in a
// collective of PETSc's that the failure skipped) prints its message with its rank and stops
// the whole run (MPI_Abort, exit 1): a run never hangs on a failure.
inline constexpr double kStrandedSeconds = 10.0;
void agree(const std::string& error);

// A failure a test injects, for the tests only (they check that the ranks fail together in
// every stage); unset, nothing happens. VOLMESH_TEST_FAIL_STAGE=STAGE@RANK (e.g. "solve@1")
// makes stage() throw on that rank once STAGE's own work is done; STAGE@RANK:start throws
// before it, so that the others wait in the stage's collectives (kStrandedSeconds).
void fail_if_injected(const char* stage, bool at_start);

// Runs one stage of a run (mesh, partition, setup, assembly, preconditioner, solve, errors,
// write) so that the ranks fail together: when fn throws on any rank (InputError, a PETSc
// error, bad_alloc), every rank throws InputError with the lowest failing rank's message
// (agree) and none is left waiting in the next stage's collectives. Every rank calls the same
// stages in the same order, and the collectives inside fn fail alike on every rank (a
// solver's convergence, PETSc's options). One rank: fn and its exceptions as they are.
template <class Fn>
void stage(const char* name, Fn&& fn) {
  if (ranks() == 1) {
    fail_if_injected(name, true);
    fn();
    fail_if_injected(name, false);
    return;
  }
  std::string error;
  try {
    fail_if_injected(name, true);
    fn();
    fail_if_injected(name, false);
  } catch (const std::bad_alloc&) {
    error = std::string(name) + ": out of memory";
  } catch (const std::exception& e) {
    error = e.what();
  }
  agree(error);
}

}  // namespace volmesh::fem
