#!/usr/bin/env bash
# CLI behaviour of the foundation: exit codes, sandbox messages, error
# locations, the instruction cap, seeded randomness, `squawk test` totals.
# usage: tests/cli.sh path/to/squawk   (run from the repo root)
set -u
sq=${1:?usage: tests/cli.sh SQUAWK_BINARY}
d=tests/data/cli
fails=0
pass=0
expect() {  # expect NAME WANT_RC PATTERN -- CMD...
  local name=$1 want=$2 pattern=$3
  shift 4
  local out rc
  out=$("$@" 2>&1)
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

expect "help"            0 "subcommands:" -- "$sq" --help
expect "version"         0 "^squawk [0-9]+\.[0-9]+\.[0-9]+" -- "$sq" --version
expect "help run"        0 "usage: squawk run" -- "$sq" help run
expect "no subcommand"   2 "" -- "$sq"
expect "unknown sub"     2 "unknown subcommand 'frobnicate'" -- "$sq" frobnicate
expect "unknown flag"    2 "unknown flag '--bogus'" -- "$sq" test --bogus
expect "missing file"    2 "missing FILE.lua" -- "$sq" run
expect "bad seed"        2 "--seed expects an integer" -- "$sq" run "$d/args.lua" --seed x
expect "args"            0 "^2	a	b$" -- "$sq" run "$d/args.lua" a b
expect "sandbox"         1 "os.execute is not allowed in the sandbox; run squawk with --unsafe" -- "$sq" run "$d/execute.lua"
expect "unsafe"          0 "^executed$" -- "$sq" run "$d/execute.lua" --unsafe
expect "module line"     1 "mod.lua:7: value too large: 6" -- "$sq" run "$d/module/main.lua"
start=$(date +%s)
expect "runaway"         1 "stopped: the script ran .* Lua instructions" -- "$sq" run "$d/runaway.lua"
elapsed=$(( $(date +%s) - start ))
if [ "$elapsed" -gt 5 ]; then echo "FAIL runaway took ${elapsed}s (want <= 5 s)"; fails=$((fails + 1)); fi
expect "test totals"     1 "^1 passed, 1 failed$" -- "$sq" test "$d/pass_fail"
expect "test location"   1 "fail.lua:1: check failed: got 4, want 5 \(arithmetic\)" -- "$sq" test "$d/pass_fail"
tmp=$(mktemp -d)
expect "demo"            0 "translator HDG KL001" -- "$sq" demo --record "$tmp/ep.jsonl" --svg "$tmp/ep.svg"
expect "demo summary"    0 "waypoint reached +yes" -- "$sq" demo --quiet
expect "demo gpt2"       0 "advisories the translator could not turn into a command: 0" -- "$sq" demo --policy gpt2 --quiet
expect "demo bad policy" 2 "expected mlp or gpt2" -- "$sq" demo --policy nope
expect "gpt2 bench help"  0 "squawk gpt2 bench" -- "$sq" gpt2 bench --help
expect "render"          0 "wrote" -- "$sq" render "$tmp/ep.jsonl" --out "$tmp/r.svg"
grep -q "<circle" "$tmp/r.svg" && grep -q "<circle" "$tmp/ep.svg" && { echo "ok   svg has circles"; pass=$((pass + 1)); } || { echo "FAIL svg"; fails=$((fails + 1)); }
printf 'episodes,eval_success_rate,eval_mean_reward\n1000,0.5,-1\n2000,0.8,-0.5\n' > "$tmp/log.csv"
expect "plot"            0 "wrote" -- "$sq" plot "$tmp"
expect "render scenario" 0 "wrote" -- "$sq" render scenarios/horizontal_cr.lua --seed 4 --out "$tmp/s.svg"
expect "render bad file" 1 "episode line 1" -- "$sq" render "$tmp/log.csv" --out "$tmp/x.svg"
rm -rf "$tmp"
a=$("$sq" run "$d/random.lua" --seed 11)
b=$("$sq" run "$d/random.lua" --seed 11)
c=$("$sq" run "$d/random.lua" --seed 12)
if [ -n "$a" ] && [ "$a" = "$b" ] && [ "$a" != "$c" ]; then echo "ok   seeded random"; pass=$((pass + 1));
else echo "FAIL seeded random: '$a' / '$b' / '$c'"; fails=$((fails + 1)); fi

# Ctrl-C during training: checkpoint saved, exit 130, --resume gives the
# parameters of an uninterrupted run.
sig=$(mktemp -d)
"$sq" train scenarios/horizontal_cr.lua --out "$sig/a" --episodes 40000 --eval-every 0 --eval-episodes 20 >"$sig/a.log" 2>&1 &
tpid=$!
sleep 2
kill -INT "$tpid"
wait "$tpid"
trc=$?
"$sq" train scenarios/horizontal_cr.lua --out "$sig/a" --episodes 40000 --eval-every 0 --eval-episodes 20 --resume >/dev/null 2>&1
"$sq" train scenarios/horizontal_cr.lua --out "$sig/b" --episodes 40000 --eval-every 0 --eval-episodes 20 >/dev/null 2>&1
if [ "$trc" -eq 130 ] && grep -q "interrupted:" "$sig/a.log" &&
   cmp -s <(tail -n +3 "$sig/a/policy.ckpt") <(tail -n +3 "$sig/b/policy.ckpt"); then
  echo "ok   train SIGINT + resume"; pass=$((pass + 1))
else echo "FAIL train SIGINT + resume: rc=$trc, $(cat "$sig/a.log")"; fails=$((fails + 1)); fi
rm -rf "$sig"

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
