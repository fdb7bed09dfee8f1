#!/usr/bin/env bash
# The scripted baselines (envs/policies/*.lua) through `squawk env run
# --policy script:FILE`: on each single-agent environment the scripted
# policy's mean episode reward over the same episodes (seed 0, squawk's class
# model, no OpenAP) must beat the random policy's, and the run must report
# success and action shares; and broken policy files must give errors that
# name the file and the value.
# usage: tests/gym_policies.sh path/to/squawk   (run from the repo root)
set -u
sq=${1:?usage: tests/gym_policies.sh SQUAWK_BINARY}
d=tests/data/policies
source "$(dirname "$0")/expect.sh"
unset SQUAWK_OPENAP

# The value of "key" in a one-line JSON object.
field() { grep -oE "\"$1\": [^,}]+" <<<"$2" | head -1 | sed 's/.*: //'; }

# beats ENV EPISODES: scripted mean reward > random mean reward.
beats() {
  local env=$1 n=$2 scripted random s r
  scripted=$("$sq" env run "envs/$env.lua" --policy "script:envs/policies/$env.lua" --episodes "$n" --json 2>&1)
  random=$("$sq" env run "envs/$env.lua" --policy random --episodes "$n" --json 2>&1)
  s=$(field mean_reward "$scripted")
  r=$(field mean_reward "$random")
  if [ -n "$s" ] && [ -n "$r" ] && awk -v s="$s" -v r="$r" 'BEGIN { exit !(s > r) }' &&
     [ "$(field success_reported "$scripted")" = "$n" ] && grep -q '"action_shares": \[\[' <<<"$scripted"; then
    echo "ok   $env: scripted $s > random $r ($n episodes), success $(field success "$scripted") of $n"
    pass=$((pass + 1))
  else
    echo "FAIL $env: scripted must beat random and report success for every episode"
    echo "    scripted: $scripted"
    echo "    random:   $random"
    fails=$((fails + 1))
  fi
}

beats descent 10
beats vertical_cr 10
beats plan_waypoint 5
beats static_obstacle 10
beats sector_cr 10
beats merge 10

e=envs/descent.lua
expect "policy success"   0 "success +3 of 3 \(100.0 %\)" -- \
  "$sq" env run $e --policy script:envs/policies/descent.lua --episodes 3
expect "policy shares"    0 "action 1 thirds 0\.[0-9]+ low, 0\.[0-9]+ middle, 0\.[0-9]+ high" -- \
  "$sq" env run $e --policy script:envs/policies/descent.lua --episodes 3
expect "policy no file"   1 "no policy file 'envs/policies/nope.lua'" -- "$sq" env run $e --policy script:envs/policies/nope.lua
expect "policy no act"    1 "no_act.lua: field 'act' must be a function" -- "$sq" env run $e --policy script:$d/no_act.lua
expect "policy wrong env" 1 "wrong_env.lua: field 'env': the policy is written for MergeEnv-v0, not DescentEnv-v0" -- \
  "$sq" env run $e --policy script:$d/wrong_env.lua
expect "policy length"    1 "two.lua: act: the action has 2 numbers; DescentEnv-v0 takes 1" -- "$sq" env run $e --policy script:$d/two.lua
expect "policy nan"       1 "nan.lua: act: action\[1\]: expected a finite number, got -?nan" -- "$sq" env run $e --policy script:$d/nan.lua
expect "policy outside"   1 "outside.lua: act: action\[1\] = 1.5 is outside \[-1, 1\]" -- "$sq" env run $e --policy script:$d/outside.lua
expect "policy error"     1 "raises.lua:3: no luck" -- "$sq" env run $e --policy script:$d/raises.lua
expect "policy bad reset" 1 "bad_reset.lua: field 'reset' must be a function or absent, got number" -- \
  "$sq" env run $e --policy script:$d/bad_reset.lua
expect "env bad success"  1 "bad_success.lua: step: info.success \(5th result\) must be a boolean, got number" -- \
  "$sq" env run $d/bad_success.lua --policy zero --episodes 1
finish
