// The one wall between squawk and MPI: the processes of a data-parallel job
// (mpirun -np N squawk ..., srun squawk ...) and the few collectives the
// learners and the evaluator need. No other file includes mpi.h.
//
// Built with MPI (CMake option SQUAWK_MPI, on when MPI is found), a process
// started by a launcher joins its job; any other process is a job of one
// (rank 0, size 1) whose collectives are identities, as is every process of a
// build without MPI (which init() refuses to start as one of several).
//
// Contracts:
// - Every rank calls the same collectives in the same order with the same
//   lengths; the results are identical on every rank.
// - For a given number of ranks and length the reduction order is fixed
//   (Open MPI picks the algorithm from those two), so a job repeats bit for
//   bit; different rank counts agree within float round-off.
// - A collective that fails (a peer rank died, the network went) does not
//   return: it prints which rank and call failed and ends the whole job.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace squawk::dist {

// Joins the job when a launcher started this process (its environment gives
// the job's size: OMPI_COMM_WORLD_SIZE from mpirun, PMI_SIZE, or
// SLURM_STEP_NUM_TASKS from srun); call once, first thing. A build without
// MPI started as one of several processes exits with status 2 and a message
// (each would run the whole job).
void init(int* argc, char*** argv);
// Leaves the job; after it no collective may be called. No-op for a job of one.
void finalize();
// Ends every rank of the job at once with exit status `code` (a job of one:
// std::exit(code)).
[[noreturn]] void abort(int code);

int rank();  // [-] 0..size()-1
int size();  // [-] >= 1
// The MPI library of a job ("Open MPI v4.1.4"), "single process" outside
// one, "none (built without MPI)".
std::string describe();

// In-place element-wise sum over the ranks.
void sum(std::span<double> x);
void sum(std::span<float> x);
// True on every rank when `flag` is true on any.
bool any(bool flag);
// Copies root's bytes into every rank's `x` (same length everywhere).
void broadcast(std::span<std::byte> x, int root);

// This rank's contiguous part [first, first + count) of `total` items:
// first = rank * total / size, so the parts cover 0..total-1 in rank order.
struct Share {
  uint64_t first = 0;  // [-]
  uint64_t count = 0;  // [-]
};
Share share(uint64_t total);

}  // namespace squawk::dist
