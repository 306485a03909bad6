#!/usr/bin/env bash
# Grooms from other tools on the command line: OBJ curves in Blender's edge-per-line form and a
# TressFX 2.x text file open directly; their flaws are repaired and counted in the metrics and
# said on stderr; strands tied at both ends (bothEndsImmovable 1) load, counted and said; a
# strand that branches is refused with its line and exit status 2.
set -eu
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
common=(--headless --no-render --solver cpu --frames 2)
python3 - "$tmp" <<'PY'
import math, sys
d = sys.argv[1]
strands = []
for s in range(40):
    a = 2 * math.pi * s / 40
    root = (0.05 * math.cos(a), 0.085, 0.05 * math.sin(a))
    strands.append([(root[0] * (1 + 0.5 * i / 7), root[1] - 0.03 * i, root[2] * (1 + 0.5 * i / 7))
                    for i in range(8)])
# Blender's form, tip first for the last strand, and a strand whose points coincide.
with open(d + "/edges.obj", "w") as f:
    f.write("# Blender 3.4.1\no groom\n")
    for s in strands:
        for p in s: f.write("v %.6f %.6f %.6f\n" % p)
    f.write("v 0 0.1 0\nv 0 0.1 0\n")
    for k in range(40):
        ids = list(range(8 * k + 1, 8 * k + 9))
        if k == 39: ids.reverse()
        for a, b in zip(ids, ids[1:]): f.write("l %d %d\n" % (a, b))
    f.write("l 321 322\n")
with open(d + "/branch.obj", "w") as f:
    f.write("v 0 0 0\nv 0 -1 0\nv 0 -2 0\nv 1 -1 0\nl 1 2 3\nl 2 4\n")
for name, both in (("text", 0), ("tied", 1)):
    with open(d + "/" + name + ".tfx", "w") as f:
        f.write("version 2.0\nscale 100\nrotation 0 0 0\ntranslation 0 0 0\n")
        f.write("bothEndsImmovable %d\nnumStrands %d\nis sorted 1\n" % (both, len(strands)))
        for i, s in enumerate(strands):
            f.write("strand %d numVerts 8 texcoord 0 0\n" % i)
            for p in s: f.write("%f %f %f\n" % p)
PY
"$bin" "$tmp/edges.obj" "${common[@]}" --metrics "$tmp/m.json" 2>"$tmp/err.txt"
cat "$tmp/err.txt"
grep -q "dropped 1 strand" "$tmp/err.txt" || { echo "FAIL: the dropped strand is not said"; exit 1; }
"$bin" "$tmp/text.tfx" "${common[@]}" --metrics "$tmp/t.json"
python3 - "$tmp/m.json" "$tmp/t.json" <<'PY'
import json, sys
m, t = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
print("obj", m["groom"], "\ntfx", t["groom"])
assert m["strands"] == 40 and t["strands"] == 40, (m["strands"], t["strands"])
assert m["groom"]["file_strands"] == 41 and m["groom"]["dropped_strands"] == 1, m["groom"]
assert m["groom"]["turned_strands"] == 1, m["groom"]
assert m["accuracy"]["nan_count"] == 0 and t["accuracy"]["nan_count"] == 0
assert t["groom"]["dropped_strands"] == 0 and t["groom"]["merged_points"] == 0, t["groom"]
assert m["groom"]["held_tips"] == 0 and t["groom"]["held_tips"] == 0
PY
"$bin" "$tmp/tied.tfx" "${common[@]}" --metrics "$tmp/tied.json" 2>"$tmp/err.txt"
grep -q "40 strands held by the head at both ends" "$tmp/err.txt" || { cat "$tmp/err.txt"; echo "FAIL: the tied strands are not said"; exit 1; }
python3 - "$tmp/tied.json" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
assert t["groom"]["held_tips"] == 40 and t["accuracy"]["nan_count"] == 0, t["groom"]
PY
set +e
out=$("$bin" "$tmp/branch.obj" "${common[@]}" 2>&1)
status=$?
set -e
echo "$out"
[ "$status" -eq 2 ] || { echo "FAIL: exit $status, expected 2"; exit 1; }
grep -q "branch.obj:6: vertex 2 (line 2) has a third edge here, after two on line 5" <<<"$out" || { echo "FAIL: no line in the message"; exit 1; }
