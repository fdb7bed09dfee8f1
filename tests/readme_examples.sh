#!/usr/bin/env bash
# Runs every README.md code block marked ```bash squawk-example, as a fresh
# clone's user would after the build: from a scratch folder that holds the
# checkout's scenarios/ and docs/ and build/squawk (the binary under test).
# Each block must exit 0; the figures README states beside them must appear.
# usage: tests/readme_examples.sh path/to/squawk   (run from the repo root)
set -u
sq=$(readlink -f "${1:?usage: tests/readme_examples.sh SQUAWK_BINARY}")
root=$(pwd)
source "$(dirname "$0")/expect.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/build"
ln -s "$sq" "$work/build/squawk"
ln -s "$root/scenarios" "$work/scenarios"
ln -s "$root/docs" "$work/docs"

# The marked blocks, one file each.
awk -v dir="$work" '
  /^```bash squawk-example[ \t]*$/ { n++; f = sprintf("%s/block%02d.sh", dir, n); inb = 1; next }
  inb && /^```/ { inb = 0; close(f); next }
  inb { print > f }
' README.md
blocks=("$work"/block*.sh)
[ -f "${blocks[0]}" ] && { echo "ok   README has ${#blocks[@]} marked blocks"; pass=$((pass + 1)); } ||
  { echo "FAIL no block marked squawk-example in README.md"; fails=$((fails + 1)); }
all="$work/all.out"
for b in "${blocks[@]}"; do
  [ -f "$b" ] || continue
  out=$(cd "$work" && timeout 120 bash -euo pipefail "$b" 2>&1 </dev/null)
  rc=$?
  printf '%s\n' "$out" >> "$all"
  if [ "$rc" -eq 0 ]; then echo "ok   $(basename "$b"): $(head -1 "$b" | cut -c1-80)"; pass=$((pass + 1))
  else echo "FAIL $(basename "$b") exited $rc:"; sed 's/^/    /' <<<"$out" | tail -15; fails=$((fails + 1)); fi
done
# What README says the blocks print.
for want in "losses of separation      0" "> ALT KL204 FL300" "ok: KL204 SPD 280" "^ALT KLM123 FL350$" \
            "^HDG KL204 70 LEFT$" "What altitude should KL204 descend to\\?" "wrote runs/first/curves.svg" \
            "wrote runs/conflict.svg" "^ +98\\.0 % +0\\.002 "; do
  grep -qE -- "$want" "$all" && { echo "ok   README figure: $want"; pass=$((pass + 1)); } ||
    { echo "FAIL README figure not printed: $want"; fails=$((fails + 1)); }
done
finish
