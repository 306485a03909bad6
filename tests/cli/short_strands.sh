#!/usr/bin/env bash
# A groom of normal strands and a few hundred of 5-10 mm (a real mohawk's, a fade's): the short
# ones ask for tens of steps a frame; under the default step budget (sim.max_substeps) the groom
# runs at 8 or fewer, the short strands counted at alpha = 1, none of them dropped; after 30
# frames of the nodding motion the strain stays within 5 % and no particle is in the head.
set -u
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib/expect.sh"

common=(--headless --no-render --quiet --solver cpu)
# The default hairstyle's 1,000 strands at rest, as a file.
"$bin" "${common[@]}" --frames 0 --set hairstyle.strands=1000 --export-hair "$tmp/base.hair" ||
  { echo "FAIL: no base groom"; exit 1; }
# 300 more: from 300 of its roots, along their first segment, 5 to 10 mm long, 6 points each.
python3 - "$tmp/base.hair" "$tmp/mohawk.hair" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
hairs, points, flags = struct.unpack_from("<III", data, 4)
off = 128
segs = struct.unpack_from("<%dH" % hairs, data, off) if flags & 1 else [struct.unpack_from("<I", data, 16)[0]] * hairs
off += 2 * hairs if flags & 1 else 0
xyz = struct.unpack_from("<%df" % (3 * points), data, off)
pts = [xyz[3 * i:3 * i + 3] for i in range(points)]
strands, at = [], 0
for s in range(hairs):
    n = segs[s] + 1
    strands.append(pts[at:at + n])
    at += n
for k in range(300):
    base = strands[(k * 7) % hairs]
    root, nxt = base[0], base[1]
    d = [b - a for a, b in zip(root, nxt)]
    norm = sum(c * c for c in d) ** 0.5
    length = 0.005 + 0.005 * k / 299.0
    strands.append([tuple(r + c / norm * length * i / 5.0 for r, c in zip(root, d)) for i in range(6)])
out = bytearray(b"HAIR")
total = sum(len(s) for s in strands)
# The counts, the arrays present (segments, points), then the defaults: segments, thickness,
# transparency, colour.
out += struct.pack("<III", len(strands), total, 3)
out += struct.pack("<Ifffff", 0, 1e-4, 0.0, 0.3, 0.2, 0.1)
out += b"\0" * (128 - len(out))
out += struct.pack("<%dH" % len(strands), *[len(s) - 1 for s in strands])
out += struct.pack("<%df" % (3 * total), *[c for s in strands for p in s for c in p])
open(sys.argv[2], "wb").write(bytes(out))
print("groom:", hairs, "strands +", 300, "of 5-10 mm,", total, "points")
PY
[ -s "$tmp/mohawk.hair" ] || { echo "FAIL: no groom written"; exit 1; }
for budget in default 64; do
  sets=(--set hairstyle.import_scale=1 --set hairstyle.resample_tolerance=0)
  [ "$budget" = default ] || sets+=(--set sim.max_substeps=$budget)
  "$bin" "$tmp/mohawk.hair" "${common[@]}" --frames 30 "${sets[@]}" --metrics "$tmp/$budget.json" \
    2>"$tmp/$budget.err" || { echo "FAIL: the run at budget $budget"; cat "$tmp/$budget.err"; exit 1; }
done
cat "$tmp/default.err"
python3 - "$tmp/default.json" "$tmp/64.json" <<'PY' || fail=1
import json, sys
m, wide = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
s, g, a = m["stiffness"], m["groom"], m["accuracy"]
print("steps", m["substeps"], "asked", s["substeps_wanted"], "at alpha 1", s["strands_at_alpha_1"],
      "of", m["strands"], "dropped", g["dropped_strands"], "max strain", a["max_strain"],
      "head penetrations", a["head_penetrations"], "; with a budget of 64:", wide["substeps"], "steps")
assert m["strands"] == 1300 and g["dropped_strands"] == 0, (m["strands"], g)
assert m["substeps"] <= 8, m["substeps"]
assert s["strands_at_alpha_1"] >= 300, s
# The strain limit (5 %) in float: a position's last bits.
assert a["max_strain"] <= 0.05 + 1e-5 and a["head_penetrations"] == 0 and a["nan_count"] == 0, a
PY
exit $fail
