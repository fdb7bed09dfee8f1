#include "app/update_log.h"

#include <cstdio>

namespace squawk::app {

Result<UpdateLog> UpdateLog::open(const std::string& path) {
  UpdateLog log;
  log.path_ = path;
  log.out_.open(path, std::ios::trunc);
  log.out_ << "episodes,mean_return,entropy,grad_norm,value_loss,advantage_sd,clip_fraction\n";
  if (!log.out_) return Status::io_error("cannot write " + path);
  return log;
}

Status UpdateLog::add(long long episodes, const rl::UpdateStats& st) {
  char row[256];
  std::snprintf(row, sizeof row, "%lld,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", episodes, st.mean_return,
                st.entropy, st.grad_norm, st.value_loss, st.advantage_sd, st.clip_fraction);
  out_ << row << std::flush;
  if (!out_) return Status::io_error("cannot write " + path_);
  return Status::ok();
}

}  // namespace squawk::app
