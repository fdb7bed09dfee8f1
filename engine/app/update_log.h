// update_log: `squawk train --env ENV.lua --update-log` writes DIR/updates.csv,
// one row per learner update (log.csv has one per evaluation interval), to
// read how a run learns: its columns are
//   episodes        [-] training episodes after the update
//   mean_return     [reward] mean return of the update's batch
//   entropy         [nats] mean policy entropy over the batch's samples (the
//                   Gaussian head's is sum over components of log sigma + 1.419)
//   grad_norm       [-] the first step's gradient norm, before clipping
//   value_loss      [reward^2] value baseline's mean squared error on the batch,
//                   before it is fitted to it
//   advantage_sd    [reward] deviation of the advantages before normalisation
//   clip_fraction   [-] ppo: share of the samples whose ratio was clipped in the last pass
// Observation only: the run computes the same with or without it.
#pragma once

#include <fstream>
#include <string>

#include "core/status.h"
#include "rl/vpg.h"

namespace squawk::app {

class UpdateLog {
 public:
  // Starts PATH over with the header; an error names PATH.
  static Result<UpdateLog> open(const std::string& path);
  // Appends the row of one update (flushed); an error names the file.
  Status add(long long episodes, const rl::UpdateStats& st);

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace squawk::app
