#!/usr/bin/env bash
# `squawk repl` from a pipe, as a person types: quit, exit and help without a
# colon; "cancel" says what it dropped or that nothing was pending; ":mode
# single" refuses when no LLM server is configured; a standing conflict is
# announced again at tLOS 120 s and 60 s, and at t = 0 with the clock held
# the predicted conflicts are announced and listed.
# usage: tests/repl_manners.sh path/to/squawk   (run from the repo root)
set -u
sq=${1:?usage: tests/repl_manners.sh SQUAWK_BINARY}
fails=0
# has NAME TEXT FIXED_STRING [absent]: TEXT contains (or, with "absent", lacks) the string.
has() {
  local found=0
  grep -qF -- "$3" <<<"$2" && found=1
  if [ "${4:-}" = absent ]; then found=$((1 - found)); fi
  if [ "$found" -eq 1 ]; then echo "ok   $1"; else
    echo "FAIL $1: ${4:+un}wanted '$3' in:"; sed 's/^/    /' <<<"$2" | head -30; fails=$((fails + 1)); fi
}
run() { printf "$1" | env -u SQUAWK_LLM_URL -u SQUAWK_LLM_MODEL timeout 60 "$sq" repl --mode offline 2>&1; }

out=$(run 'help\ncancel\nKL204 descend\ncancel\n:mode single\n:mode multi\nexit\n!CRE AFTER1 A320 52 4 90 FL100 250\n')
has "help without a colon prints the help" "$out" ":state            the clock"
has "help is not a question" "$out" "I did not understand" absent
has "cancel with nothing pending says so" "$out" "nothing to cancel: no question was pending"
has "cancel says what it dropped" "$out" "cancelled (dropped: KL204 descend)"
has ":mode single refuses without an LLM server" "$out" ":mode single needs an LLM server"
has ":mode multi refuses without an LLM server" "$out" ":mode multi needs an LLM server"
has ":mode does not claim to switch" "$out" "  mode single" absent
has "exit without a colon leaves (the next line is not run)" "$out" "AFTER1" absent
out=$(run 'quit\nhelp\n')
has "quit without a colon leaves" "$out" ":state" absent

out=$(run '!CRE BAW1 B744 52 3.2 90 FL300 280\n!CRE DLH2 A320 52 4.8 270 FL300 280\n!ASAS ON\n:run 200\n')
has "a conflict is announced when it starts" "$out" "] conflict BAW1 & DLH2: loss of separation in"
has "reminder at tLOS 120 s" "$out" "still conflict BAW1 & DLH2: loss of separation in 120 s"
has "reminder at tLOS 60 s" "$out" "still conflict BAW1 & DLH2: loss of separation in 60 s"

out=$(printf ':state\n' | env -u SQUAWK_LLM_URL timeout 60 "$sq" repl scenarios/scope_demo.scn --mode offline 2>&1)
has "t = 0, clock held: the predicted conflict is announced" "$out" "[t=     0 s] conflict DLH4AX & KLM1234: loss of separation in 200 s"
has "t = 0, clock held: :state lists it" "$out" "conflicts: 1"

[ "$fails" -eq 0 ] && echo "all passed" || { echo "$fails failed"; exit 1; }
