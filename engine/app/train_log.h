// The folder of a training run (--out DIR), shared by the MLP and GPT-2
// learners: DIR/checkpoint.ckpt holds the learner's state that --resume
// continues from, DIR/log.csv one row per evaluation interval, first column
// the episodes trained so far.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>

#include "app/cli.h"
#include "core/status.h"
#include "rl/checkpoint.h"
#include "rl/evaluator.h"
#include "rl/vpg.h"

namespace squawk::app {

struct RunFolder {
  std::string checkpoint;  // DIR/checkpoint.ckpt
  std::string log;         // DIR/log.csv
  bool resuming = false;   // --resume was given and the checkpoint exists
};

// Creates DIR when missing. A run that starts now (no --resume, or nothing
// to resume), or one resumed with --override, records its settings in
// DIR/run.json (out_guard.h); `args` are
// the learner's parsed flags, already passed through resolve_train_argv.
// In a data-parallel job (dist/comm.h) rank 0 alone creates and records the
// folder and every rank gets rank 0's answer; error on a rank that cannot
// see the checkpoint rank 0 resumes from (DIR must be on a file system that
// every rank shares).
Result<RunFolder> open_run_folder(const std::string& dir, const Args& args);

// A resumed run continues its own seed's random streams: error naming the
// checkpoint when it was trained with another seed.
Status check_resume_seed(const RunFolder& run, uint64_t trained, uint64_t requested);

// Prints where an interrupted run stands and how to continue it.
void print_interrupted(const RunFolder& run, const rl::TrainProgress& p);

// log.csv (written by rank 0 alone in a data-parallel job; the other ranks'
// logs keep the interval sums only): each row the means over the interval's updates of the training
// return and success (kept in TrainProgress's interval sums, so they survive
// --resume), the last update's entropy and gradient norm, and the validation
// result.
class TrainLog {
 public:
  // Resuming: keeps the header and the rows up to `episodes` (the resumed
  // checkpoint's), so --resume never repeats a row; otherwise the file starts
  // over with the header.
  static Result<TrainLog> open(const RunFolder& run, long long episodes);

  // Adds one update to p's open interval.
  void add(rl::TrainProgress& p, const rl::UpdateStats& st);
  // Writes (flushed) the interval's row and opens the next interval in p.
  Status row(rl::TrainProgress& p, const rl::EvalResult& ev);

 private:
  std::string path_;
  std::ofstream out_;
  double entropy_ = 0.0, grad_norm_ = 0.0;  // the last update's
};

}  // namespace squawk::app
