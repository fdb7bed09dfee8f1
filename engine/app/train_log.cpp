#include "app/train_log.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "app/out_guard.h"
#include "core/files.h"
#include "dist/comm.h"

namespace squawk::app {

namespace {

constexpr const char* kHeader =
    "episodes,updates,wall_s,train_mean_return,train_success_rate,entropy,grad_norm,"
    "eval_success_rate,eval_mean_reward,eval_std_reward\n";

// Keeps the header and the rows of `path` whose episodes are <= `episodes`.
// Rows written after a checkpoint that failed to save (a full disk) go.
Status trim(const std::string& path, long long episodes) {
  SQUAWK_ASSIGN_OR_RETURN(std::string text, files::read(path));
  std::istringstream in(text);
  std::string line, out;
  bool header = true;
  while (std::getline(in, line)) {
    if (header || std::strtoll(line.c_str(), nullptr, 10) <= episodes) out += line + "\n";
    header = false;
  }
  return files::write_atomic(path, out);
}

}  // namespace

Result<RunFolder> open_run_folder(const std::string& dir, const Args& args) {
  RunFolder run{dir + "/checkpoint.ckpt", dir + "/log.csv", false};
  run.resuming = args.has("--resume") && files::exists(run.checkpoint);
  if (dist::rank() == 0) {
    SQUAWK_RETURN_IF_ERROR(files::make_dirs(dir));
    if (!run.resuming || args.has("--override")) SQUAWK_RETURN_IF_ERROR(record_run(dir, args));
  }
  std::byte resuming{static_cast<unsigned char>(run.resuming)};
  dist::broadcast({&resuming, 1}, 0);
  if (static_cast<bool>(resuming) && !run.resuming)
    return Status::not_found("rank " + std::to_string(dist::rank()) + " cannot see " + run.checkpoint +
                             ", which rank 0 resumes from: the run folder must be on a file system every rank shares");
  run.resuming = static_cast<bool>(resuming);
  return run;
}

Status check_resume_seed(const RunFolder& run, uint64_t trained, uint64_t requested) {
  if (trained == requested) return Status::ok();
  return Status::invalid("checkpoint " + run.checkpoint + " was trained with seed " + std::to_string(trained) +
                         ", not " + std::to_string(requested));
}

void print_interrupted(const RunFolder& run, const rl::TrainProgress& p) {
  std::printf("interrupted: %s holds the policy after %lld episodes (%lld updates); "
              "--resume continues from there exactly\n",
              run.checkpoint.c_str(), p.episodes, p.updates);
}

Result<TrainLog> TrainLog::open(const RunFolder& run, long long episodes) {
  if (dist::rank() > 0) return TrainLog{};
  if (run.resuming && files::exists(run.log)) {
    SQUAWK_RETURN_IF_ERROR(trim(run.log, episodes));
  } else {
    SQUAWK_RETURN_IF_ERROR(files::write_atomic(run.log, kHeader));
  }
  TrainLog log;
  log.path_ = run.log;
  log.out_.open(run.log, std::ios::app);
  if (!log.out_) return Status::io_error("cannot write " + run.log);
  return log;
}

void TrainLog::add(rl::TrainProgress& p, const rl::UpdateStats& st) {
  p.interval_return += st.mean_return;
  p.interval_success += st.success_rate;
  ++p.interval_updates;
  entropy_ = st.entropy;
  grad_norm_ = st.grad_norm;
}

Status TrainLog::row(rl::TrainProgress& p, const rl::EvalResult& ev) {
  const double k = p.interval_updates > 0 ? static_cast<double>(p.interval_updates) : 1.0;
  char row[256];
  std::snprintf(row, sizeof row, "%lld,%lld,%.2f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n", p.episodes, p.updates,
                p.wall_s, p.interval_return / k, p.interval_success / k, entropy_, grad_norm_, ev.success_rate,
                ev.mean_reward, ev.std_reward);
  p.interval_return = p.interval_success = 0.0;
  p.interval_updates = 0;
  if (path_.empty()) return Status::ok();  // not rank 0
  out_ << row << std::flush;
  if (!out_) return Status::io_error("cannot write " + path_);
  return Status::ok();
}

}  // namespace squawk::app
