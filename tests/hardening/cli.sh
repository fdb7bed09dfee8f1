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

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
