#!/usr/bin/env bash
# `squawk repl` from a pipe, as a person types: quit, exit and help without a
# colon; "cancel" says what it dropped or that nothing was pending; ":mode
# single" refuses when no LLM server is configured; a standing conflict is
# announced again at tLOS 120 s and 60 s, and at t = 0 with the clock held
# the predicted conflicts are announced and listed; TrafScript typed runs as
# typed, destructive requests wait for a yes, what is not simulated is named
# a close callsign is asked about, and a leftover plain word (never a negation) may be
# answered "ignore it" (docs/translator_trust.md).
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

# TrafScript typed in English mode runs as typed, any case, and the trace says so
out=$(run '!CRE KL204 B738 52 4 90 FL200 250\nFF 60\nhold\nOP\n:trace\nSCHEDULE 60 HOLD\nkl204 atalt fl080 spd\n')
has "FF 60 typed runs for its 60 s" "$out" "fast-forwarded 60 s: t = 0.0 s -> 60.0 s"
has "hold in lower case stops the clock" "$out" "> HOLD"
has "OP typed runs the clock" "$out" "> OP"
has "the trace names the typed node" "$out" "typed     TrafScript typed in English mode: runs as that command: OP"
has "a condition's command typed runs as typed" "$out" "> SCHEDULE 60 HOLD"
has "a condition's command that does not parse is asked about" "$out" "? ATALT carries 'spd'"
# destructive and global requests wait for a yes; no drops them
out=$(run '!CRE KL204 B738 52 4 90 FL200 250\n!CRE KL205 B738 52 5 90 FL200 250\ndelete all aircraft\nno\nRESET\nno\nIC scenarios/scope_demo.scn\nno\nswitch conflict resolution off for all aircraft\nno\n:state\n')
has "deleting several aircraft asks first" "$out" "? Delete 2 aircraft (KL204, KL205)? (yes or no)"
has "RESET asks first" "$out" "? Reset the simulation?"
has "IC asks first" "$out" "? Load scenario scenarios/scope_demo.scn?"
has "resolution off for all asks first" "$out" "? Switch conflict resolution off for every aircraft?"
has "no drops the deletion" "$out" "cancelled (dropped: delete all aircraft)"
has "nothing ran: both aircraft still fly" "$out" "KL205"
has "nothing ran: no aircraft deleted" "$out" "deleted" absent
# what squawk does not simulate is named, not misunderstood
out=$(run '!CRE KL204 B738 52 4 90 FL200 250\n!DEFWPT SQK01 52.1 4.1\nKL204 hold at SQK01\nKL204 cleared ILS approach runway 27\nKL204 squawk 7700\nKL204 contact approach 119.7\n')
has "holding patterns named" "$out" "squawk does not simulate holding patterns ('hold at SQK01')"
has "approach clearances named" "$out" "squawk does not simulate approach clearances"
has "transponder codes named" "$out" "squawk does not simulate transponder codes ('squawk 7700')"
has "frequencies named" "$out" "squawk does not simulate radio frequencies"
has "none of them is 'not understood'" "$out" "I did not understand" absent
# with one aircraft in the sky a close callsign is asked about, never taken
out=$(run '!CRE ACA851 A320 52 4 90 FL200 250\nair canada eight five climb FL300\nAC 851 climb FL300\n')
has "a callsign missing a digit asks with one aircraft" "$out" "? Did you mean ACA851? I heard ACA85."
has "an airline's two-letter code asks" "$out" "? Did you mean ACA851? I heard AC851."
has "neither ran" "$out" "> ALT" absent

out=$(run "!CRE KL9 A320 52 4 90 FL200 250\nKL9 don't climb FL300\nignore it\nKL9 climb FL300 gently\nignore it\n")
has "a negation asks" "$out" "What does 'don't' mean?   (answer, or say cancel)"
has "a negation is never ignored: the request runs only after 'gently' is" "$out" "> ALT KL9 FL300"
has "an unknown word offers ignore" "$out" "What does 'gently' mean?   (answer, say ignore if it means nothing, or cancel)"
n=$(grep -c "^> ALT KL9" <<<"$out")
if [ "$n" -eq 1 ]; then echo "ok   one ALT ran (after 'gently' was ignored)"; else echo "FAIL $n ALT ran"; fails=$((fails + 1)); fi

[ "$fails" -eq 0 ] && echo "all passed" || { echo "$fails failed"; exit 1; }
