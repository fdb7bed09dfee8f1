// `squawk train --env ENV.lua --out DIR [--levels K | --gaussian] [--hidden W,...]
// [learner flags]`: the MLP learner (rl/vpg.h) on an environment written in
// Lua, its Box action discretised into K levels per component (default 5)
// and a categorical head over the K^d grid classes (script/lua_batch_env.h),
// or with --gaussian (one-component Boxes) the MLP's Gaussian head (mean from
// the network, a learned state-independent log sigma) over the continuous
// action, its sample clipped to [-1, 1] and mapped onto the Box.
// Writes DIR/checkpoint.ckpt (with the learner's state) and DIR/best.ckpt
// (the highest validation mean reward) at each evaluation, DIR/policy.ckpt
// (the last policy) at the end and DIR/log.csv; `squawk env run ENV.lua
// --policy mlp:CKPT` evaluates a checkpoint.
#pragma once

#include "app/cli.h"

namespace squawk::app {

// `args`: train's parsed flags, with --env.
int cmd_train_env(const Args& args);

}  // namespace squawk::app
