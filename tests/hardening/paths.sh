#!/usr/bin/env bash
# Walks the path audit table of docs/sandbox_audit.md: every probe, with every
# hostile path of its kind, must be refused with "not allowed", and nothing
# outside the sandbox may be read, run or created.
# usage: tests/hardening/paths.sh path/to/squawk   (run from the repo root)
set -u
sq=${1:?usage: tests/hardening/paths.sh SQUAWK_BINARY}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
mkdir -p "$t/secret/sub" "$t/script/inner" "$t/out"
echo "SECRET-CONTENT" >"$t/secret/secret.txt"
echo 'print("EVIL-RAN") return {}' >"$t/secret/evil.lua"
cp "$t/secret/evil.lua" "$t/secret/init.lua"
ln -s "$t/secret/secret.txt" "$t/script/link_file"
ln -s "$t/secret" "$t/script/link_dir"
ln -s "$t/secret/created_by_read" "$t/script/dangling"
ln -s "$t/secret/secret.txt" "$t/script/inner/leak"
ln -s "$t/secret/evil.lua" "$t/script/req_link.lua"
ln -s "$t/secret" "$t/script/req_dir"
ln -s "$t/secret/created.txt" "$t/out/dangling_w"
ln -s "$t/secret" "$t/out/link_dir_w"
ln -s ../secret/created_rel.txt "$t/out/dangling_rel"
# A GPT-2 checkpoint whose header names a prompt file outside the sandbox.
python3 - "$root/models/horizontal_cr_gpt2_tiny.ckpt" "$t/script/evil.ckpt" "$t/secret/evil.lua" <<'PY'
import json, sys
data = open(sys.argv[1], "rb").read()
magic_end = data.index(b"\n")
head_end = data.index(b"\n", magic_end + 1)
header = json.loads(data[magic_end + 1:head_end])
header["prompt"] = sys.argv[3]
open(sys.argv[2], "wb").write(data[:magic_end + 1] + json.dumps(header).encode() + data[head_end:])
PY
# The probes: the table rows between the markers, as a Lua module.
python3 - "$root/docs/sandbox_audit.md" "$t/script/probes.lua" <<'PY'
import sys
text = open(sys.argv[1]).read()
rows = text.split("<!-- audit-table-begin -->")[1].split("<!-- audit-table-end -->")[0].splitlines()
out = ["return {"]
for row in rows[3:]:
    cells = [c.strip() for c in row.strip().strip("|").split("|")]
    if len(cells) != 4:
        continue
    api, kind, _, probe = cells
    out.append("  { api = [==[%s]==], kind = %r, probe = %s }," % (api, kind, probe.strip("`")))
out.append("}")
open(sys.argv[2], "w").write("\n".join(out) + "\n")
PY
cp "$here/paths_walker.lua" "$t/script/walker.lua"
out=$(cd "$root" && timeout 120 "$sq" run "$t/script/walker.lua" "$t" --out "$t/out" 2>&1)
rc=$?
echo "$out"
fail=0
[ "$rc" -eq 0 ] || { echo "FAIL walker exited $rc"; fail=1; }
grep -q "^FAIL" <<<"$out" && fail=1
grep -q "SECRET-CONTENT\|EVIL-RAN" <<<"$out" && { echo "FAIL content from outside the sandbox was read or run"; fail=1; }
for f in created.txt created_rel.txt created_by_read x.txt; do
  [ -e "$t/secret/$f" ] && { echo "FAIL $t/secret/$f was created outside --out"; fail=1; }
done
n=$(grep -c "^ok" <<<"$out")
[ "$n" -ge 80 ] || { echo "FAIL only $n probes ran (expected >= 80)"; fail=1; }
[ "$fail" -eq 0 ] && echo "paths: $n refusals checked"
exit "$fail"
