#!/usr/bin/env bash
# Paired comparison of two deterministic policies on a Lua environment, as
# docs/gym_envs.md's "Against every baseline" reports it: episode k (seed
# SEED + k, k = 0 .. EPISODES-1) is played once by each policy with
# `squawk env run ENV --policy P --seed SEED+k --episodes 1` (--greedy for mlp:
# checkpoints, their mean or mode; script: rules are deterministic), and the
# per-episode differences A - B are summarised: their mean, its standard error
# (sd / sqrt(n)), and in how many episodes A is better, equal, worse.
# usage: bench/gym_paired.sh SQUAWK ENV.lua POLICY_A POLICY_B [EPISODES [SEED]]   (from the source root)
#   OpenAP: SQUAWK_OPENAP, else ../shared/openap/data when present (else squawk's class model).
set -eu
usage="usage: bench/gym_paired.sh SQUAWK ENV.lua POLICY_A POLICY_B [EPISODES [SEED]]"
sq=${1:?$usage}
env=${2:?$usage}
a=${3:?$usage}
b=${4:?$usage}
episodes=${5:-200}
seed=${6:-0}
openap=${SQUAWK_OPENAP:-}
[ -z "$openap" ] && [ -d ../shared/openap/data ] && openap=../shared/openap/data
flags=(--episodes 1 --json)
[ -n "$openap" ] && flags+=(--openap "$openap")

# reward POLICY K: the reward of episode SEED + K under POLICY.
reward() {
  local greedy=()
  [[ $1 == mlp:* ]] && greedy=(--greedy)
  "$sq" env run "$env" --policy "$1" "${greedy[@]}" --seed $((seed + $2)) "${flags[@]}" |
    python3 -c 'import json, sys; print(json.loads(sys.stdin.read())["mean_reward"])'
}

for ((k = 0; k < episodes; ++k)); do
  echo "$(reward "$a" "$k") $(reward "$b" "$k")"
done | python3 -c '
import math, sys
a_name, b_name = sys.argv[1], sys.argv[2]
pairs = [tuple(map(float, line.split())) for line in sys.stdin if line.strip()]
d = [x - y for x, y in pairs]
n = len(d)
mean = sum(d) / n
sd = math.sqrt(sum((x - mean) ** 2 for x in d) / (n - 1)) if n > 1 else 0.0
better = sum(x > 1e-9 for x in d); worse = sum(x < -1e-9 for x in d)
print("A %s: mean %.3f; B %s: mean %.3f" % (a_name, sum(p[0] for p in pairs) / n, b_name, sum(p[1] for p in pairs) / n))
print("A - B over %d paired episodes: mean %+.3f, standard error %.3f; A better in %d, equal in %d, worse in %d" % (
    n, mean, sd / math.sqrt(n), better, n - better - worse, worse))
' "$a" "$b"
