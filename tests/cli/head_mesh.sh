#!/usr/bin/env bash
# head.mesh: a closed OBJ head runs (hair grown on it, kept outside it); a malformed one is
# refused with exit status 2 and its file and line, from --set, from a preset and --validate.
set -u
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib/expect.sh"

# A UV sphere of radius 0.1 m about the origin (the head's cranium), poles at +-y.
python3 - "$tmp/head.obj" <<'PY'
import math, sys
stacks, slices, r = 24, 32, 0.1
out = ["# a round head"]
out.append("v 0 %.6f 0" % r)
for i in range(1, stacks):
    t = math.pi * i / stacks
    for j in range(slices):
        p = 2 * math.pi * j / slices
        out.append("v %.6f %.6f %.6f" % (r * math.sin(t) * math.sin(p), r * math.cos(t),
                                          r * math.sin(t) * math.cos(p)))
out.append("v 0 %.6f 0" % -r)
ring = lambda i, j: 2 + (i - 1) * slices + j % slices
for j in range(slices):
    out.append("f 1 %d %d" % (ring(1, j), ring(1, j + 1)))
for i in range(1, stacks - 1):
    for j in range(slices):
        out.append("f %d %d %d %d" % (ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)))
last = 2 + (stacks - 1) * slices
for j in range(slices):
    out.append("f %d %d %d" % (ring(stacks - 1, j), last, ring(stacks - 1, j + 1)))
open(sys.argv[1], "w").write("\n".join(out) + "\n")
PY
# The same sphere with a face index out of range on its 40th face's line.
lines=$(wc -l <"$tmp/head.obj")
faceline=$(grep -n '^f' "$tmp/head.obj" | sed -n 40p | cut -d: -f1)
awk -v n="$faceline" 'NR == n { print "f 1 2 99999"; next } { print }' "$tmp/head.obj" >"$tmp/bad.obj"
printf '{"collision": {"head_shape": "sdf"}, "head": {"mesh": "bad.obj"}}' >"$tmp/bad.json"
printf '{"collision": {"head_shape": "sdf"}, "head": {"mesh": "head.obj"}, "hairstyle": {"strands": 200}}' >"$tmp/good.json"
echo "head.obj: $lines lines; bad.obj: line $faceline out of range"

common=(--headless --no-render --solver cpu --quiet --frames 5)
expect 2 "$tmp/bad.obj:$faceline: face vertex index 99999 is out of range" -- "${common[@]}" \
  --set collision.head_shape=sdf --set head.mesh="$tmp/bad.obj"
expect 2 "bad.json: head.mesh: $tmp/bad.obj:$faceline: face vertex index 99999" -- "$tmp/bad.json" "${common[@]}"
expect 2 "bad.json: head.mesh: $tmp/bad.obj:$faceline:" -- --validate "$tmp/bad.json"
expect 2 "$tmp/none.obj" -- "${common[@]}" --set head.mesh="$tmp/none.obj"
expect 0 "good.json: ok" -- --validate "$tmp/good.json"
# The good head runs: no NaN, no particle left inside it.
expect 0 "" -- "$tmp/good.json" "${common[@]}" --metrics "$tmp/m.json"
python3 - "$tmp/m.json" <<'PY' || fail=1
import json, sys
m = json.load(open(sys.argv[1]))
a = m["accuracy"]
print("strands", m["strands"], "nan", a["nan_count"], "head_penetrations", a["head_penetrations"])
assert m["strands"] == 200 and a["nan_count"] == 0
assert a["head_penetrations"] == 0, a
PY
exit $fail
