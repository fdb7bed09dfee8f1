#!/usr/bin/env bash
# The REPL transcript in docs/translator_trust.md ("A session") is what the REPL does: the lines
# typed in it (the block's lines that start with no space, '>' or '?') are piped to
# `squawk repl --echo --mode offline scenarios/translator_trust.scn`, whose output must be the
# block, line for line. --print prints the fresh transcript instead (to paste into the page).
# usage: tests/repl_transcript.sh path/to/squawk [--print]   (run from the repo root)
set -u
sq=${1:?usage: tests/repl_transcript.sh SQUAWK_BINARY [--print]}
doc=docs/translator_trust.md
# the fenced block after the marker line
block=$(awk '/^<!-- transcript: tests\/repl_transcript.sh -->$/ {m = 1; next}
             m == 1 && /^```/ {m = 2; next}
             m == 2 && /^```/ {exit}
             m == 2 {print}' "$doc")
if [ -z "$block" ]; then echo "FAIL no transcript block after the marker in $doc"; exit 1; fi
typed=$(grep -v '^[ >?]' <<<"$block")
fresh=$(printf '%s\n' "$typed" | env -u SQUAWK_LLM_URL -u SQUAWK_LLM_MODEL -u SQUAWK_NAVDATA timeout 60 \
  "$sq" repl --echo --mode offline scenarios/translator_trust.scn 2>&1)
if [ "${2:-}" = --print ]; then printf '%s\n' "$fresh"; exit 0; fi
if [ "$fresh" = "$block" ]; then echo "ok   the transcript in $doc is what the REPL does"; exit 0; fi
echo "FAIL the transcript in $doc differs from the REPL (diff: page, REPL):"
diff <(printf '%s\n' "$block") <(printf '%s\n' "$fresh")
exit 1
