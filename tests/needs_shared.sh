#!/usr/bin/env bash
# Runs a test that reads the shared data folder (../shared: BlueSky's navdata
# and scenarios, OpenAP, recorded traces, corpora), or reports it skipped.
# usage: tests/needs_shared.sh SHARED_DIR COMMAND [ARGS...]
# Exit 77 (ctest's SKIP_RETURN_CODE) when SHARED_DIR is absent.
shared=${1:?usage: tests/needs_shared.sh SHARED_DIR COMMAND [ARGS...]}
shift
if [ ! -d "$shared" ]; then
  echo "skipped: $shared is absent (shared data: BlueSky navdata and scenarios, OpenAP, traces; see docs/testing.md)"
  exit 77
fi
exec "$@"
