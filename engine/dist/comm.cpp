#include "dist/comm.h"

#include <cstdio>
#include <cstdlib>
#include <vector>

#if SQUAWK_HAVE_MPI
#include <mpi.h>
#endif

namespace squawk::dist {

Share share(uint64_t total) {
  const auto r = static_cast<uint64_t>(rank()), n = static_cast<uint64_t>(size());
  const uint64_t first = r * total / n;
  return {first, (r + 1) * total / n - first};
}

namespace {

// The number of processes a launcher started this one among (0: no launcher).
long launched_size() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"})
    if (const char* n = std::getenv(v)) return std::strtol(n, nullptr, 10);
  return 0;
}

}  // namespace

bool any(bool flag) {
  double x = flag ? 1.0 : 0.0;
  sum(std::span<double>(&x, 1));
  return x > 0.0;
}

#if SQUAWK_HAVE_MPI

namespace {

bool joined = false;
int my_rank = 0, my_size = 1;

// A failed MPI call: names the rank and the call, then ends the job.
void check(int rc, const char* call) {
  if (rc == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int len = 0;
  MPI_Error_string(rc, text, &len);
  std::fprintf(stderr,
               "squawk: rank %d of %d: %s failed (%.*s): a peer rank has died or the network failed; "
               "ending the job (the last complete checkpoint is intact; --resume continues)\n",
               my_rank, my_size, call, len, text);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::exit(1);
}

}  // namespace

void init(int* argc, char*** argv) {
  if (joined || launched_size() == 0) return;
  MPI_Init(argc, argv);
  joined = true;
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &my_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &my_size);
}

void finalize() {
  if (!joined) return;
  MPI_Finalize();
  joined = false;
}

void abort(int code) {
  std::fflush(stdout);
  std::fflush(stderr);
  if (joined) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

int rank() { return my_rank; }
int size() { return my_size; }

std::string describe() {
  if (!joined) return "single process";
  char lib[MPI_MAX_LIBRARY_VERSION_STRING];
  int len = 0;
  MPI_Get_library_version(lib, &len);
  const std::string name(lib, static_cast<size_t>(len));
  return name.substr(0, name.find(','));
}

void sum(std::span<double> x) {
  if (my_size > 1 && !x.empty())
    check(MPI_Allreduce(MPI_IN_PLACE, x.data(), static_cast<int>(x.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD),
          "MPI_Allreduce");
}

void sum(std::span<float> x) {
  if (my_size > 1 && !x.empty())
    check(MPI_Allreduce(MPI_IN_PLACE, x.data(), static_cast<int>(x.size()), MPI_FLOAT, MPI_SUM, MPI_COMM_WORLD),
          "MPI_Allreduce");
}

void broadcast(std::span<std::byte> x, int root) {
  if (my_size > 1 && !x.empty())
    check(MPI_Bcast(x.data(), static_cast<int>(x.size()), MPI_BYTE, root, MPI_COMM_WORLD), "MPI_Bcast");
}

#else  // a job of one

void init(int*, char***) {
  if (launched_size() < 2) return;
  std::fprintf(stderr,
               "squawk: started as one of %ld processes by an MPI launcher, but built without MPI, so each would "
               "run the whole job alone: rebuild with libopenmpi-dev installed (tools/setup), or run without "
               "mpirun/srun\n",
               launched_size());
  std::exit(2);
}
void finalize() {}
void abort(int code) {
  std::fflush(stdout);
  std::exit(code);
}
int rank() { return 0; }
int size() { return 1; }
std::string describe() { return "none (built without MPI)"; }
void sum(std::span<double>) {}
void sum(std::span<float>) {}
void broadcast(std::span<std::byte>, int) {}

#endif

}  // namespace squawk::dist
