#!/usr/bin/env bash
# Issue 12 (hardening) regression checks of the command line: caps, refused
# options, error output. Each check names the point of the issue it covers.
# usage: tests/hardening/cli.sh path/to/squawk   (run from the repo root)
set -u
sq=${1:?usage: tests/hardening/cli.sh SQUAWK_BINARY}
d=tests/hardening
fails=0
pass=0
expect() {  # expect NAME WANT_RC PATTERN -- CMD...
  local name=$1 want=$2 pattern=$3
  shift 4
  local out rc
  out=$(timeout 60 "$@" 2>&1 </dev/null)
  rc=$?
  if [ "$rc" -ne "$want" ] || ! grep -qE -- "$pattern" <<<"$out"; then
    echo "FAIL $name: rc=$rc (want $want), output:"
    sed 's/^/    /' <<<"$out" | head -20
    fails=$((fails + 1))
  else
    echo "ok   $name"
    pass=$((pass + 1))
  fi
}
llm=(--llm-url http://127.0.0.1:1 --llm-model m)

expect "11 timeout 1e-9"     2 "timeout 1e-09 s is not within" -- "$sq" llm chat hi "${llm[@]}" --timeout 1e-9
expect "11 timeout nan"      2 "is not within|expects a number" -- "$sq" llm chat hi "${llm[@]}" --timeout nan
expect "18 context wraps"    2 "--context 4294967297: expected 1 to" -- "$sq" llm chat hi "${llm[@]}" --context 4294967297
expect "12 max-reply-mb 0"   2 "--max-reply-mb 0" -- "$sq" llm chat hi "${llm[@]}" --max-reply-mb 0

lim=(--max-instructions 200000)
expect "6 coroutines"        1 "coroutines.lua:3: stopped: the script ran 200000 Lua instructions" -- "$sq" run $d/coroutines.lua "${lim[@]}"
expect "6 coroutine catch"   1 "stopped: the script ran 200000" -- "$sq" run $d/coroutine_catch.lua "${lim[@]}"
expect "6 step 1e8"          1 "sim_step.lua:4: stopped: the script ran" -- "$sq" run $d/sim_step.lua step 1e8 "${lim[@]}"
expect "6 step 1e15"         1 "argument 'n': expected a whole number in \[0, 1000000000\]" -- "$sq" run $d/sim_step.lua step 1e15
expect "6 run_for 1e12"      1 "sim_step.lua:4: stopped: the script ran" -- "$sq" run $d/sim_step.lua run_for 1e12 "${lim[@]}"
expect "6 run_until 1e12"    1 "sim_step.lua:4: stopped: the script ran" -- "$sq" run $d/sim_step.lua run_until 1e12 "${lim[@]}"
expect "6 evaluate 1e12"     1 "field 'episodes': expected a whole number in \[1, 1000000\]" -- "$sq" run $d/evaluate.lua 1e12
expect "18 evaluate nan"     1 "field 'episodes': .* got NaN" -- "$sq" run $d/evaluate.lua 0/0
expect "7 per call"          0 "^steps 3000$" -- "$sq" run $d/reward_per_call.lua $d/reward_scenario.lua "${lim[@]}"
expect "7 refuse -1"         2 "--max-instructions expects a count >= 0" -- "$sq" run $d/coroutines.lua --max-instructions -1
expect "4 env.new self"      1 "more than 8 scenario files loading each other" -- "$sq" run $d/nested_env.lua
expect "4 IC self"           1 "more than 16 nested IC/PCALLs" -- "$sq" scn $d/ic_self.scn
expect "5 read refused"       1 "reading '/etc/passwd' is not allowed" -- "$sq" run $d/read_file.lua /etc/passwd
expect "5 --allow-read"      0 "^root:" -- "$sq" run $d/read_file.lua /etc/passwd --allow-read /etc
expect "5 key hidden"        0 "^key=nil$" -- env SQUAWK_LLM_API_KEY=sekrit "$sq" run $d/read_file.lua /etc/passwd --allow-read /etc
expect "5 --unsafe"          0 "^key=sekrit$" -- env SQUAWK_LLM_API_KEY=sekrit "$sq" run $d/read_file.lua /etc/passwd --unsafe
expect "9 SCHEDULE loop"      1 "more than 100000 queued commands at one time" -- "$sq" scn $d/sch2.scn
expect "9 self-scheduling"   1 "more than 100000 queued commands at one time" -- "$sq" scn $d/sch_grow.scn
expect "9 DT 1e-300"         1 "is not in \[0.001, 60\] s" -- "$sq" scn $d/dt_tiny.scn
expect "9 --max-wall"        1 "s of wall-clock time \(--max-wall\)" -- "$sq" scn $d/sch_grow.scn --until 100000 --max-wall 1
out=$("$sq" scn $d/dump_fail.scn --dump-json 2>/dev/null); err=$("$sq" scn $d/dump_fail.scn --dump-json 2>&1 >/dev/null)
if grep -q '"simt"' <<<"$out" && ! grep -q KL9 <<<"$out" && grep -q "ALT KL9 FL100: argument 1: no aircraft 'KL9'" <<<"$err"; then
  echo "ok   10 dump-json errors on stderr"; pass=$((pass + 1))
else echo "FAIL 10 dump-json errors on stderr: out=$out err=$err"; fails=$((fails + 1)); fi

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
