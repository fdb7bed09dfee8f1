#!/usr/bin/env bash
# Issue 12 (hardening) regression checks of the command line: caps, refused
# options, error output. Each check names the point of the issue it covers.
# usage: tests/hardening/cli.sh path/to/squawk   (run from the repo root)
set -u
sq=${1:?usage: tests/hardening/cli.sh SQUAWK_BINARY}
d=tests/hardening
source "$(dirname "$0")/../expect.sh"
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
expect "6 --max-seconds"      1 "spin.lua:2: stopped: the call ran longer than 1.0+ s of wall-clock time" -- "$sq" run $d/spin.lua --max-seconds 1 --max-instructions 0
expect "6 pattern in C"      124 "ran 2 s past --max-seconds 1 inside one C function" -- "$sq" run $d/pattern.lua --max-seconds 1
expect "6 --max-seconds -1"  2 "--max-seconds expects seconds >= 0" -- "$sq" run $d/spin.lua --max-seconds -1
expect "52 --max-memory"     1 "Lua memory reached 64 MiB, the limit per VM" -- "$sq" run $d/memory.lua --max-memory 64
expect "52 --max-memory -1"  2 "--max-memory expects MiB" -- "$sq" run $d/memory.lua --max-memory -1
expect "52 __gc loop"        1 "gc_loop.lua:6: stopped: the script ran 2000000 Lua instructions" -- "$sq" run $d/gc_loop.lua collect --max-instructions 2000000
expect "52 __gc at exit"     0 "^script done$" -- "$sq" run $d/gc_loop.lua --max-instructions 2000000
expect "52 __gc at exit, wall" 0 "^script done$" -- "$sq" run $d/gc_loop.lua --max-instructions 0 --max-seconds 1
expect "52 record /dev/full" 1 "cannot write '/dev/full': No space left on device" -- "$sq" eval scenarios/horizontal_cr.lua --episodes 2 --record /dev/full
fifo=$(mktemp -u); mkfifo "$fifo"; (cat "$fifo" >"$fifo.out" &)
expect "52 record FIFO"      0 "success" -- "$sq" eval scenarios/horizontal_cr.lua --episodes 2 --record "$fifo"
if [ -p "$fifo" ]; then echo "ok   52 FIFO stays a FIFO"; pass=$((pass + 1)); else echo "FAIL 52 FIFO was replaced"; fails=$((fails + 1)); fi
rm -f "$fifo" "$fifo.out"
expect "7 per call"          0 "^steps 3000$" -- "$sq" run $d/reward_per_call.lua $d/reward_scenario.lua "${lim[@]}"
expect "7 refuse -1"         2 "--max-instructions expects a count >= 0" -- "$sq" run $d/coroutines.lua --max-instructions -1
expect "18 scenario NaN"      0 "field 'intruders': expected a whole number .* got NaN" -- "$sq" run $d/load_scenario.lua $d/bad_numbers_scenario.lua
expect "4 env.new self"      1 "more than 8 scenario files loading each other" -- "$sq" run $d/nested_env.lua
expect "4 IC self"           1 "more than 16 nested IC/PCALLs" -- "$sq" scn $d/ic_self.scn
expect "5 read refused"       1 "'/etc/passwd': reading it is not allowed" -- "$sq" run $d/read_file.lua /etc/passwd
expect "5 --allow-read"      0 "^root:" -- "$sq" run $d/read_file.lua /etc/passwd --allow-read /etc
expect "5 key hidden"        0 "^key=nil$" -- env SQUAWK_LLM_API_KEY=sekrit "$sq" run $d/read_file.lua /etc/passwd --allow-read /etc
expect "5 --unsafe"          0 "^key=sekrit$" -- env SQUAWK_LLM_API_KEY=sekrit "$sq" run $d/read_file.lua /etc/passwd --unsafe
expect "9 SCHEDULE loop"      1 "more than 100000 queued commands at one time" -- "$sq" scn $d/sch2.scn
expect "9 self-scheduling"   1 "more than 100000 queued commands at one time" -- "$sq" scn $d/sch_grow.scn
expect "9 DT 1e-300"         1 "is not in \[0.001, 60\] s" -- "$sq" scn $d/dt_tiny.scn
expect "9 --max-time wall"   1 "after 1 s of wall-clock time \(--max-time\)" -- "$sq" scn $d/sch_every.scn --until 100000000 --max-time 1
expect "9 --max-sim-time"    0 "ran to t = 20.00 s" -- "$sq" scn $d/sch_every.scn --max-sim-time 20
out=$("$sq" scn $d/dump_fail.scn --dump-json 2>/dev/null); err=$("$sq" scn $d/dump_fail.scn --dump-json 2>&1 >/dev/null)
if grep -q '"simt"' <<<"$out" && ! grep -q KL9 <<<"$out" && grep -q "ALT KL9 FL100: argument 1: no aircraft 'KL9'" <<<"$err"; then
  echo "ok   10 dump-json errors on stderr"; pass=$((pass + 1))
else echo "FAIL 10 dump-json errors on stderr: out=$out err=$err"; fails=$((fails + 1)); fi
# 17: an install layout (bin/ + share/squawk/) and a moved binary use their own home.
tmp=$(mktemp -d)
mkdir -p "$tmp/inst/bin" "$tmp/inst/share/squawk" "$tmp/copy"
cp "$sq" "$tmp/inst/bin/squawk"
cp -r scripts prompts scenarios models "$tmp/inst/share/squawk/"
cp "$d/home.lua" "$tmp/inst/share/squawk/scripts/home_check.lua"
expect "17 install layout"   0 "home=$tmp/inst/share/squawk" -- "$tmp/inst/bin/squawk" run "$tmp/inst/share/squawk/scripts/home_check.lua"
cp "$sq" "$tmp/copy/squawk"
expect "17 SQUAWK_HOME"      0 "^ok$" -- env SQUAWK_HOME="$tmp/inst/share/squawk" "$tmp/copy/squawk" run "$tmp/inst/share/squawk/scripts/home_check.lua"
rm -rf "$tmp"
# 52 point 2: the REPL's session module (a home's scripts/translate/repl.lua)
# raising when C++ reads it: clean messages, the REPL goes on, no panic.
tmp=$(mktemp -d)
cp -r scripts "$tmp/"
cp "$d/hostile_repl_module.lua" "$tmp/scripts/translate/repl.lua"
expect "52 repl module raises" 1 "the translator did not load \(translate.repl.new: reading field 'new': \(error object is a table value\)\)" -- env SQUAWK_HOME="$tmp" "$sq" repl
cp "$d/hostile_repl_session.lua" "$tmp/scripts/translate/repl.lua"
expect "52 repl session raises" 1 "session:handle: reading field 'handle': \(error object is a table value\)" -- env SQUAWK_HOME="$tmp" bash -c 'echo "KL1 climb FL300" | "$0" repl' "$sq"
rm -rf "$tmp"
# 52 point 3: conflict bookkeeping at its cap says so (scn summary, REPL
# events), naming the cap and the flag; under the cap nothing is said.
capnote="conflict detection hit its cap of 5 stored pairs in [0-9]+ detections?: conflicts beyond it were not listed \(--max-conflict-pairs N raises the cap\)"
expect "52 cap, scn"         0 "^note: $capnote" -- "$sq" scn tests/serve/converging.scn --until 5 --max-conflict-pairs 5
out=$("$sq" scn tests/serve/converging.scn --until 5 2>&1)
if grep -q "conflicts: 19;" <<<"$out" && ! grep -q "cap of" <<<"$out"; then echo "ok   52 no cap, no note"; pass=$((pass + 1));
else echo "FAIL 52 no cap, no note: $out"; fails=$((fails + 1)); fi
expect "52 cap, repl"        0 "\[t= +[0-9]+ s\] $capnote" -- bash -c 'echo ":run 5" | "$0" repl tests/serve/converging.scn --max-conflict-pairs 5' "$sq"
expect "52 cap flag refused" 2 "--max-conflict-pairs expects a count >= 1" -- "$sq" scn tests/serve/converging.scn --max-conflict-pairs 0
# The default cap (100 000 pairs): 450 aircraft within a mile of each other
# make 101 025 pairs.
scn=$(mktemp --suffix .scn)
awk 'BEGIN { print "00:00:00.00>ASAS ON"; for (i = 1; i <= 450; i++)
  printf "00:00:00.00>CRE X%d B738 %.4f %.4f %d FL200 250\n", i, 52 + (i % 30) * 0.0005, 4 + int(i / 30) * 0.0008, i % 360 }' >"$scn"
expect "52 default cap"      0 "^note: conflict detection hit its cap of 100000 stored pairs" -- "$sq" scn "$scn" --until 2
rm -f "$scn"
# 16: a checkpoint that failed to save (full disk) after its log row was
# written: --resume drops the row instead of repeating it.
tmp=$(mktemp -d)
tr=(train scenarios/horizontal_cr.lua --eval-every 64 --eval-episodes 8 --episodes 128 --out "$tmp/run" --quiet)
"$sq" "${tr[@]}" --stop-at 64 >/dev/null 2>&1
cp "$tmp/run/checkpoint.ckpt" "$tmp/ckpt_64"
"$sq" "${tr[@]}" --resume >/dev/null 2>&1
cp "$tmp/ckpt_64" "$tmp/run/checkpoint.ckpt"  # the save at 128 episodes "failed"
"$sq" "${tr[@]}" --resume >/dev/null 2>&1
rows=$(cut -d, -f1 "$tmp/run/log.csv" | tail -n +2 | tr '\n' ' ')
if [ "$rows" = "64 128 " ]; then echo "ok   16 resume after a failed save"; pass=$((pass + 1));
else echo "FAIL 16 resume after a failed save: episodes column '$rows'"; fails=$((fails + 1)); fi
rm -rf "$tmp"
# 13: every reply malformed: the translation graph falls back to the offline
# grammar, so single-agent mode scores what offline mode scores.
if command -v python3 >/dev/null; then
  tmp=$(mktemp -d)
  head -4 tests/data/translate_heldout.tsv > "$tmp/c.tsv"
  python3 $d/bad_llm_server.py > "$tmp/port" &
  spid=$!
  for _ in 1 2 3 4 5 6 7 8 9 10; do [ -s "$tmp/port" ] && break; sleep 0.3; done
  off=$("$sq" eval-translate "$tmp/c.tsv" --mode offline 2>&1 | grep overall)
  single=$(SQUAWK_LLM_URL=http://127.0.0.1:$(cat "$tmp/port") SQUAWK_LLM_MODEL=m timeout 60 "$sq" eval-translate "$tmp/c.tsv" --mode single 2>&1 | grep overall)
  expect "1 __gc in on_token"  0 "after: false .*finalized" -- "$sq" run $d/gc_in_on_token.lua "http://127.0.0.1:$(cat "$tmp/port")" --unsafe
  kill "$spid" 2>/dev/null
  if [ -n "$off" ] && [ "$off" = "$single" ]; then echo "ok   13 graph falls back from malformed replies"; pass=$((pass + 1));
  else echo "FAIL 13 graph fallback: offline '$off' single '$single'"; fails=$((fails + 1)); fi
  rm -rf "$tmp"
else
  echo "skip 13 graph fallback: no python3"
fi

# JSON lines quote corpus ids and text; bytes that are not UTF-8 become U+FFFD
# (nlohmann's dump threw: "internal error", exit 1).
tsv=$(mktemp)
printf 'id\tsetup\tutterance\texpected\tcategory\nx\3771\t\tKL204 \377 climb\tALT KL204 FL300\tx\n' >"$tsv"
expect "sib jsonl non-UTF-8" 0 $'"id":"x\xef\xbf\xbd1"' -- "$sq" translate --tsv "$tsv" --jsonl
rm -f "$tsv"

finish
