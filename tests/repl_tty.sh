#!/usr/bin/env bash
# `squawk repl` on a real terminal (a tmux pane): Tab completion of commands
# and callsigns, Ctrl-C clearing the line without leaving, the running clock
# moving time between keystrokes and its conflict messages appearing above
# the line being typed, Ctrl-D ending the session.
# usage: tests/repl_tty.sh path/to/squawk   (run from the repo root)
set -u
sq=$(realpath "${1:?usage: tests/repl_tty.sh SQUAWK_BINARY}")
if ! command -v tmux >/dev/null; then
  echo "skipped: tmux is not installed (tools/setup installs it)"
  exit 0
fi
tmp=$(mktemp -d)
sock="squawk-repl-$$"
cleanup() { tmux -L "$sock" kill-server 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
fails=0
pane() { tmux -L "$sock" capture-pane -p -t repl 2>/dev/null; }
# wait_for NAME PATTERN: the pane shows PATTERN within 10 s.
wait_for() {
  for _ in $(seq 100); do
    if pane | grep -qE -- "$2"; then echo "ok   $1"; return 0; fi
    sleep 0.1
  done
  echo "FAIL $1: no '$2' on the screen:"
  pane | sed 's/^/    /'
  fails=$((fails + 1))
  return 1
}
keys() { tmux -L "$sock" send-keys -t repl "$@"; }

tmux -L "$sock" new-session -d -s repl -x 200 -y 60 "HOME=$tmp $sq repl --mode offline; echo REPL-EXIT=\$?; sleep 30"
wait_for "banner" "squawk repl: English or !TrafScript"
keys '!CRE KL204 A320 52 4 90 FL250 280' Enter
wait_for "create" "ok: CRE KL204"
keys '!HD' Tab
wait_for "tab completes a command" 'squawk> !HDG ?$'
keys 'KL2' Tab
wait_for "tab completes a callsign" 'squawk> !HDG KL204 ?$'
keys '180' Enter
wait_for "completed line runs" "ok: HDG KL204 180"
keys 'KL204 turn left heading 010'
wait_for "typed line shown" 'squawk> KL204 turn left heading 010$'
keys C-c
wait_for "Ctrl-C clears the line" '\^C'
keys ':state' Enter
wait_for "session alive after Ctrl-C" "t = 0.0 s, 1 aircraft"
if pane | grep -q "HDG KL204 10"; then
  echo "FAIL Ctrl-C: the cleared line ran"; fails=$((fails + 1))
else
  echo "ok   the cleared line did not run"
fi
keys '!CRE BAW1 B744 50 4 90 FL300 280' Enter '!CRE DLH2 A320 50 4.8 270 FL300 280' Enter '!ASAS ON' Enter
wait_for "head-on pair" "ok: ASAS ON"
keys ':clock 100' Enter
wait_for "clock started" "clock running at 100 x real time"
keys 'BAW1 tur'
wait_for "the running clock reports the conflict again (tLOS 60 s)" "still conflict BAW1 & DLH2: loss of separation in"
wait_for "typed text kept below it" 'squawk> BAW1 tur$'
keys C-u ':state' Enter
wait_for "running clock moved time" "t = [1-9][0-9]*\.[0-9] s, 3 aircraft"
keys C-d
wait_for "Ctrl-D ends the session" "REPL-EXIT=0"
echo "$fails failed"
[ "$fails" -eq 0 ]
