#!/usr/bin/env bash
# A simulated groom exported to cyHair and opened again gives the same points; a broken
# groom file is refused with its byte offset and exit status 2.
set -eu
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
common=(--headless --no-render --solver cpu --quiet --set hairstyle.strands=300 --set head.motion=none)
"$bin" "${common[@]}" --frames 5 --export-hair "$tmp/a.hair"
# Open the export as a groom: no refitting (scale 1), no resampling, no simulation.
"$bin" "$tmp/a.hair" "${common[@]}" --frames 0 --set hairstyle.import_scale=1 \
  --set hairstyle.resample_tolerance=0 --export-hair "$tmp/b.hair" --metrics "$tmp/m.json"
python3 - "$tmp/a.hair" "$tmp/b.hair" "$tmp/m.json" <<'PY'
import json, struct, sys
def read(path):
    data = open(path, "rb").read()
    assert data[:4] == b"HAIR", path
    hairs, points, flags = struct.unpack_from("<III", data, 4)
    off = 128
    segs = None
    if flags & 1:
        segs = struct.unpack_from("<%dH" % hairs, data, off); off += 2 * hairs
    pts = struct.unpack_from("<%df" % (3 * points), data, off)
    return hairs, points, segs, pts
a, b = read(sys.argv[1]), read(sys.argv[2])
assert a[0] == b[0] == 300 and a[1] == b[1], (a[:2], b[:2])
if a[2] is not None and b[2] is not None:
    assert a[2] == b[2]
worst = max(abs(x - y) for x, y in zip(a[3], b[3]))
print("strands", a[0], "points", a[1], "largest difference (m)", worst)
assert worst < 1e-6, worst
m = json.load(open(sys.argv[3]))
assert m["groom"]["file_strands"] == 300, m["groom"]
PY
# The same frame as OBJ curves (the form Blender reads: one "l i j" an edge), then opened as a
# groom: the same strands and points as the cyHair export.
"$bin" "${common[@]}" --frames 5 --export-hair "$tmp/a.obj"
"$bin" "$tmp/a.obj" "${common[@]}" --frames 0 --set hairstyle.import_scale=1 \
  --set hairstyle.resample_tolerance=0 --export-hair "$tmp/c.hair"
python3 - "$tmp/a.hair" "$tmp/a.obj" "$tmp/c.hair" <<'PY'
import struct, sys
def read(path):
    data = open(path, "rb").read()
    hairs, points, flags = struct.unpack_from("<III", data, 4)
    off = 128
    segs = struct.unpack_from("<%dH" % hairs, data, off) if flags & 1 else None
    off += 2 * hairs if flags & 1 else 0
    return hairs, points, segs, struct.unpack_from("<%df" % (3 * points), data, off)
hair = read(sys.argv[1])
v, l = [], []
for line in open(sys.argv[2]):
    t = line.split()
    if t and t[0] == "v":  # each number read as the float it was written from
        v.append(tuple(struct.unpack("<f", struct.pack("<f", float(x)))[0] for x in t[1:]))
    elif t and t[0] == "l":
        assert len(t) == 3, line  # two indices a line, never a polyline
        l.append((int(t[1]), int(t[2])))
assert len(v) == hair[1], (len(v), hair[1])
assert len(l) == hair[1] - hair[0], (len(l), hair[1], hair[0])
assert all(j == i + 1 for i, j in l)
worst = max(abs(a - b) for p, q in zip(v, zip(*[iter(hair[3])] * 3)) for a, b in zip(p, q))
assert worst == 0.0, worst  # the shortest text that reads back to the same float
back = read(sys.argv[3])
assert back[0] == hair[0] and back[1] == hair[1], (back[:2], hair[:2])
worst = max(abs(a - b) for a, b in zip(hair[3], back[3]))
print("OBJ:", len(v), "vertices,", len(l), "edges; read back as", back[0], "strands, largest difference (m)", worst)
assert worst < 1e-6, worst
PY
# A truncated file: the reader names the byte offset.
head -c 150 "$tmp/a.hair" >"$tmp/short.hair"
set +e
out=$("$bin" "$tmp/short.hair" --headless --solver cpu --frames 1 2>&1)
status=$?
set -e
echo "$out"
[ "$status" -eq 2 ] || { echo "FAIL: exit $status, expected 2"; exit 1; }
grep -q "byte" <<<"$out" || { echo "FAIL: no byte offset in the message"; exit 1; }
