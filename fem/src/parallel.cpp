#include "volmesh/fem/parallel.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/types.hpp"

#ifdef VOLMESH_HAVE_PETSC
#include <petscsys.h>
#endif

namespace volmesh::fem {
namespace {

struct State {
  std::vector<std::string> arguments;  // PETSc's options from the command line
  std::string misplaced;               // what is wrong with where they stand
  bool started = false;
  bool distributed = false;
  int rank = 0, ranks = 1;
};

State& state() {
  static State s;
  return s;
}

// "-name" whose name starts with a letter and is letters, digits and underscores, with at
// least one underscore: PETSc's option names (-ksp_rtol, -pc_type, -log_view). volmesh's own
// options are "--name" or one letter ("-o"); expressions such as "-x*y" do not match.
bool is_petsc_option(const char* word) {
  if (word[0] != '-' || !std::isalpha(static_cast<unsigned char>(word[1]))) return false;
  bool underscore = false;
  for (const char* c = word + 1; *c; ++c) {
    if (*c == '_') underscore = true;
    else if (!std::isalnum(static_cast<unsigned char>(*c))) return false;
  }
  return underscore;
}

// An option of volmesh's own: "--name", or '-' and a letter that is not PETSc's ("-o"; a
// negative number is a value).
bool is_volmesh_option(const char* word) {
  if (word[0] != '-') return false;
  if (word[1] == '-') return word[2] != '\0';
  return std::isalpha(static_cast<unsigned char>(word[1])) && !is_petsc_option(word);
}

// Set by mpirun (Open MPI, MPICH/PMI, PMIx): the run has several processes from the start.
bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") ||
         std::getenv("PMIX_RANK");
}

}  // namespace

Session::Session(int& argc, char** argv) {
  State& s = state();
  int kept = 1;
  const char* first = nullptr;  // the first PETSc option
  for (int i = 1; i < argc; ++i) {
    const char* word = argv[i];
    if (std::strcmp(word, "--") == 0) {
      s.arguments.insert(s.arguments.end(), argv + i + 1, argv + argc);
      break;
    }
    if (!first && !is_petsc_option(word)) {
      argv[kept++] = argv[i];
      continue;
    }
    if (!first) first = word;
    if (!is_volmesh_option(word)) {
      s.arguments.emplace_back(word);  // a PETSc option or its value
    } else if (s.misplaced.empty()) {
      s.misplaced = std::string(word) + " follows the PETSc option " + first +
                    ": PETSc options go after the subcommand's own arguments, or after --";
    }
  }
  argc = kept;
  argv[argc] = nullptr;
  if (petsc_built() && launched_by_mpirun()) {
    start_petsc();
    s.distributed = true;
  }
}

const std::vector<std::string>& petsc_arguments() { return state().arguments; }
const std::string& petsc_options_misplaced() { return state().misplaced; }
bool petsc_started() { return state().started; }
bool distributed_run() { return state().distributed; }
int rank() { return state().rank; }
int ranks() { return state().ranks; }

void fail_if_injected(const char* stage, bool at_start) {
  static const std::string injected = [] {
    const char* v = std::getenv("VOLMESH_TEST_FAIL_STAGE");
    return std::string(v ? v : "");
  }();
  if (injected.empty()) return;
  const std::string here =
      std::string(stage) + "@" + std::to_string(rank()) + (at_start ? ":start" : "");
  if (injected != here) return;
  throw std::runtime_error("stage " + std::string(stage) + " failed on rank " +
                           std::to_string(rank()) + " (VOLMESH_TEST_FAIL_STAGE, a test's failure)");
}

#ifdef VOLMESH_HAVE_PETSC

bool petsc_built() { return true; }

std::string backend_summary() {
  return "linear solvers: Eigen (LDLT, CG + incomplete Cholesky), PETSc " +
         std::to_string(PETSC_VERSION_MAJOR) + "." + std::to_string(PETSC_VERSION_MINOR) + "." +
         std::to_string(PETSC_VERSION_SUBMINOR) + " (CG + hypre BoomerAMG)";
}

// The ranks' agreements (agree) on their own communicator: a rank that failed waits there
// without matching a collective that PETSc starts on PETSC_COMM_WORLD on the others.
MPI_Comm& agreement_comm() {
  static MPI_Comm comm = MPI_COMM_NULL;
  return comm;
}

void start_petsc() {
  State& s = state();
  if (s.started) return;
  // PETSc keeps the argument vector: it lives as long as the state.
  static std::string program = "volmesh";
  static std::vector<char*> words;
  words.assign(1, program.data());
  for (std::string& a : s.arguments) words.push_back(a.data());
  words.push_back(nullptr);
  int count = static_cast<int>(words.size()) - 1;
  char** vector = words.data();
  if (PetscInitialize(&count, &vector, nullptr, nullptr) != 0)
    throw std::runtime_error("PETSc failed to start");
  // Errors come back as codes, which the backend turns into exceptions with one line.
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  MPI_Comm_rank(PETSC_COMM_WORLD, &s.rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &s.ranks);
  MPI_Comm_dup(PETSC_COMM_WORLD, &agreement_comm());
  s.started = true;
}

Session::~Session() {
  if (!state().started) return;
  MPI_Comm_free(&agreement_comm());
  PetscFinalize();
}

void sum_over_ranks(double* values, std::size_t count) {
  if (ranks() == 1) return;
  // In chunks: MPI counts are int.
  constexpr std::size_t kChunk = std::size_t(1) << 28;
  for (std::size_t at = 0; at < count; at += kChunk)
    MPI_Allreduce(MPI_IN_PLACE, values + at, static_cast<int>(std::min(kChunk, count - at)),
                  MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
}

double max_over_ranks(double value) {
  if (ranks() == 1) return value;
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  return value;
}

std::vector<double> gather_to_all(const double* mine, std::size_t count) {
  if (ranks() == 1) return std::vector<double>(mine, mine + count);
  if (count > std::size_t(kMaxIndex)) throw std::runtime_error("gather: more values than 32-bit counts allow");
  std::vector<int> counts(ranks()), starts(ranks(), 0);
  const int n = static_cast<int>(count);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, PETSC_COMM_WORLD);
  std::int64_t total = 0;
  for (int r = 0; r < ranks(); ++r) {
    starts[r] = static_cast<int>(total);
    total += counts[r];
  }
  if (total > kMaxIndex) throw std::runtime_error("gather: more values than 32-bit counts allow");
  std::vector<double> out(total);
  MPI_Allgatherv(mine, n, MPI_DOUBLE, out.data(), counts.data(), starts.data(), MPI_DOUBLE,
                 PETSC_COMM_WORLD);
  return out;
}

std::vector<std::vector<double>> exchange(const std::vector<std::vector<double>>& to) {
  if (ranks() == 1) return to;
  const int count = ranks();
  std::vector<int> send_count(count), receive_count(count), send_at(count + 1, 0),
      receive_at(count + 1, 0);
  for (int r = 0; r < count; ++r) {
    if (to[r].size() > std::size_t(kMaxIndex))
      throw std::runtime_error("exchange: more values than 32-bit counts allow");
    send_count[r] = static_cast<int>(to[r].size());
  }
  MPI_Alltoall(send_count.data(), 1, MPI_INT, receive_count.data(), 1, MPI_INT, PETSC_COMM_WORLD);
  for (int r = 0; r < count; ++r) {
    send_at[r + 1] = send_at[r] + send_count[r];
    receive_at[r + 1] = receive_at[r] + receive_count[r];
  }
  std::vector<double> sent, received(receive_at[count]);
  sent.reserve(send_at[count]);
  for (const std::vector<double>& v : to) sent.insert(sent.end(), v.begin(), v.end());
  MPI_Alltoallv(sent.data(), send_count.data(), send_at.data(), MPI_DOUBLE, received.data(),
                receive_count.data(), receive_at.data(), MPI_DOUBLE, PETSC_COMM_WORLD);
  std::vector<std::vector<double>> from(count);
  for (int r = 0; r < count; ++r)
    from[r].assign(received.begin() + receive_at[r], received.begin() + receive_at[r + 1]);
  return from;
}

namespace {

void broadcast_from(std::vector<char>& bytes, int root, MPI_Comm comm = PETSC_COMM_WORLD) {
  std::int64_t size = static_cast<std::int64_t>(bytes.size());
  MPI_Bcast(&size, 1, MPI_INT64_T, root, comm);
  bytes.resize(size);
  // Large meshes in chunks: MPI counts are int.
  constexpr std::int64_t kChunk = std::int64_t(1) << 30;
  for (std::int64_t at = 0; at < size; at += kChunk)
    MPI_Bcast(bytes.data() + at, static_cast<int>(std::min(kChunk, size - at)), MPI_CHAR, root,
              comm);
}

}  // namespace

void broadcast(std::vector<char>& bytes) {
  if (ranks() == 1) return;
  broadcast_from(bytes, 0);
}

std::vector<std::vector<char>> gather_bytes_to_all(const std::vector<char>& mine) {
  std::vector<std::vector<char>> out(ranks());
  out[rank()] = mine;
  for (int r = 0; r < ranks(); ++r) broadcast_from(out[r], r);
  return out;
}

void barrier() {
  if (ranks() > 1) MPI_Barrier(PETSC_COMM_WORLD);
}

namespace {

// How long a rank waiting for the others sleeps between looks: short beside any stage, long
// enough that the waiting costs no core.
constexpr auto kIdlePoll = std::chrono::milliseconds(1);

// Returns once every rank has called it, sleeping meanwhile: Open MPI's blocking collectives
// poll a core, which the rank still working (rank 0 meshing, with its threads) needs. A rank
// that failed waits kStrandedSeconds at most; false then.
bool wait_for_every_rank(bool failed) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  MPI_Request request;
  MPI_Ibarrier(agreement_comm(), &request);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return true;
    if (failed && std::chrono::duration<double>(Clock::now() - start).count() > kStrandedSeconds)
      return false;
    std::this_thread::sleep_for(kIdlePoll);
  }
}

}  // namespace

void agree(const std::string& error) {
  if (ranks() == 1) {
    if (!error.empty()) throw InputError(error);
    return;
  }
  if (!wait_for_every_rank(!error.empty())) {
    // The others wait where this rank will not come: only stopping the run ends it.
    std::cerr << "volmesh: error: " << error << " (rank " << rank()
              << " alone; stopping every rank)" << std::endl;
    MPI_Abort(PETSC_COMM_WORLD, 1);
  }
  int failed = error.empty() ? ranks() : rank();
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MIN, agreement_comm());
  if (failed == ranks()) return;
  // The failing rank's message to every rank (rank 0 prints it).
  std::vector<char> message(error.begin(), error.end());
  broadcast_from(message, failed, agreement_comm());
  throw InputError(std::string(message.begin(), message.end()));
}

#else

bool petsc_built() { return false; }
std::string backend_summary() {
  return "linear solvers: Eigen (LDLT, CG + incomplete Cholesky); built without PETSc";
}
void start_petsc() {}
Session::~Session() = default;
void sum_over_ranks(double*, std::size_t) {}
double max_over_ranks(double value) { return value; }
std::vector<double> gather_to_all(const double* mine, std::size_t count) {
  return std::vector<double>(mine, mine + count);
}
std::vector<std::vector<double>> exchange(const std::vector<std::vector<double>>& to) {
  return to;
}
void broadcast(std::vector<char>&) {}
std::vector<std::vector<char>> gather_bytes_to_all(const std::vector<char>& mine) {
  return {mine};
}
void barrier() {}
void agree(const std::string& error) {
  if (!error.empty()) throw InputError(error);
}

#endif

}  // namespace volmesh::fem
