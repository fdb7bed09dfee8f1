# Shared by the command-line test scripts (tests/cli.sh, tests/hardening/cli.sh):
#   expect NAME WANT_RC PATTERN -- CMD...
# runs CMD (stdin closed, at most 180 s: a hang's bound, wide enough for
# the sanitizer build on a loaded host), and passes when it exits with WANT_RC
# and its output (stdout and stderr) matches the extended regex PATTERN.
# `finish` prints the totals and fails the script when any check failed.
fails=0
pass=0
expect() {
  local name=$1 want=$2 pattern=$3
  shift 4
  local out rc
  out=$(timeout 180 "$@" 2>&1 </dev/null)
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
finish() {
  echo "$pass passed, $fails failed"
  [ "$fails" -eq 0 ]
}
