#!/usr/bin/env bash
# Step-by-step agreement of Lua environments with BlueSky-Gym's own code on
# the real BlueSky (bench/gym_ref/compare.py), 3 episodes of one environment (one
# random, one action 0, one action -1); the 30-episode figures are in
# docs/gym_envs.md. Needs ../shared/bluesky_ref set up (its setup.sh builds the
# BlueSky tree compare.py finds) and the BlueSky-Gym source in $BSGYM_SRC (a
# checkout or bare git dir) or ../shared/bluesky-gym.
# usage: tests/gym_ref.sh SQUAWK ENV [compare.py flags...] (also $GYM_REF_FLAGS); exit 77 (skipped) when a piece is absent.
set -u
squawk=${1:?usage: tests/gym_ref.sh SQUAWK ENV [compare.py flags...]}
env=${2:?usage: tests/gym_ref.sh SQUAWK ENV [compare.py flags...]}
shift 2
root=$(cd "$(dirname "$0")/.." && pwd)
if [ ! -d "$root/../shared/bluesky_ref" ]; then
  echo "skipped: $root/../shared/bluesky_ref is absent (the real BlueSky for the reference comparison)"
  exit 77
fi
if [ ! -x /usr/bin/python3 ]; then
  echo "skipped: no /usr/bin/python3 (Debian's, with numpy, runs BlueSky)"
  exit 77
fi
# exit 77 from compare.py: it found no BlueSky tree or BlueSky-Gym source
exec /usr/bin/python3 "$root/bench/gym_ref/compare.py" --env "$env" --episodes 3 --squawk "$squawk" ${GYM_REF_FLAGS:-} "$@"
