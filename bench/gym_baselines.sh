#!/usr/bin/env bash
# The baselines table of docs/gym_envs.md: for each single-agent BlueSky-Gym
# environment written in Lua (envs/), `squawk env run` with the random policy,
# the do-nothing policy (action 0 in every component: no heading or speed
# change; in DescentEnv and VerticalCREnv a vertical speed of 0, which
# BlueSky flies as its default 1500 ft/min climb) and the scripted policy
# envs/policies/ENV.lua, over the same episodes (seed S + k). Prints one
# markdown row per environment and policy: success (each env file's
# info.success; docs/gym_envs.md says what it means per env), mean episode
# reward (σ), mean episode length, and per action component the share of
# steps in the lower / middle / upper third of its range.
# A trained policy is one more `row` line per environment below.
# usage: bench/gym_baselines.sh SQUAWK [EPISODES [SEED]]   (from the source root)
#   OpenAP: SQUAWK_OPENAP, else ../shared/openap/data when present (else squawk's class model).
set -eu
sq=${1:?usage: bench/gym_baselines.sh SQUAWK [EPISODES [SEED]]}
episodes=${2:-200}
seed=${3:-0}
openap=${SQUAWK_OPENAP:-}
[ -z "$openap" ] && [ -d ../shared/openap/data ] && openap=../shared/openap/data
flags=(--episodes "$episodes" --seed "$seed" --json)
[ -n "$openap" ] && flags+=(--openap "$openap")

# row ENV LABEL POLICY: one table row from `squawk env run envs/ENV.lua --policy POLICY`.
row() {
  local env=$1 label=$2 policy=$3
  "$sq" env run "envs/$env.lua" --policy "$policy" "${flags[@]}" | python3 -c '
import json, sys
label = sys.argv[1]
r = json.loads(sys.stdin.read())
ok = "n/a" if r["success"] is None else "%.1f %%" % (100.0 * r["success"] / r["success_reported"])
shares = "; ".join("/".join("%.2f" % x for x in s) for s in r["action_shares"])
print("| %s | %s | %s | %.2f (σ %.2f) | %.1f | %s |" % (
    r["env"], label, ok, r["mean_reward"], r["std_reward"], r["mean_length"], shares))
' "$label"
}

model="squawk's class model"
[ -n "$openap" ] && model="OpenAP ($openap)"
echo "$episodes episodes from seed $seed, $model"
echo
echo "| environment | policy | success | mean reward (σ) | mean length | action shares (lower/middle/upper third; per component) |"
echo "|---|---|---|---|---|---|"
for env in descent vertical_cr plan_waypoint static_obstacle sector_cr merge; do
  row "$env" random random
  row "$env" "do nothing" zero
  row "$env" scripted "script:envs/policies/$env.lua"
done
