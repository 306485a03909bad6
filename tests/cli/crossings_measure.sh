#!/usr/bin/env bash
# --metrics in a mode without strand contacts measures crossings with a search of its own: what
# that search cannot follow (segments in too dense a crowd) is said of the measure, never as
# contacts missing from a mode that has none; in a strand-contact mode it is said of the contacts.
set -u
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
# A crowd: 300 strands in one bundle (each the default hairstyle's first strand, moved by under
# half a millimetre) and a hair radius of 2 cm, so every segment has thousands of candidates.
"$bin" --headless --no-render --quiet --solver cpu --frames 0 --set hairstyle.strands=300 \
  --export-hair "$tmp/base.hair" || { echo "FAIL: no base groom"; exit 1; }
python3 - "$tmp/base.hair" "$tmp/bundle.hair" <<'PY'
import random, struct, sys
data = bytearray(open(sys.argv[1], "rb").read())
hairs, points, flags = struct.unpack_from("<III", data, 4)
assert flags & 1 and flags & 2, flags
segs = struct.unpack_from("<%dH" % hairs, data, 128)
off = 128 + 2 * hairs
first = [struct.unpack_from("<3f", data, off + 12 * i) for i in range(segs[0] + 1)]
rnd = random.Random(7)
out = bytearray(data[:128])
out[4:16] = struct.pack("<III", hairs, hairs * len(first), 3)
out += struct.pack("<%dH" % hairs, *([segs[0]] * hairs))
for s in range(hairs):
    d = [rnd.uniform(-4e-4, 4e-4) for _ in range(3)]
    for p in first:
        out += struct.pack("<3f", *(c + e for c, e in zip(p, d)))
open(sys.argv[2], "wb").write(bytes(out))
PY
crowd=(--headless --no-render --solver gpu --frames 2 --set hairstyle.import_scale=1
       --set hairstyle.resample_tolerance=0 --set collision.radius=0.02 --set collision.margin=0.01)
for mode in head strands; do
  "$bin" "$tmp/bundle.hair" "${crowd[@]}" --set collision.mode=$mode --metrics "$tmp/$mode.json" \
    2>"$tmp/$mode.err" || { echo "FAIL: the $mode run exited $?"; cat "$tmp/$mode.err"; fail=1; }
  echo "--- $mode:"; grep -E "warning|note" "$tmp/$mode.err" | grep -v "software renderer"
done
grep -q "the hair-crossings measure (--metrics) left out up to" "$tmp/head.err" ||
  { echo "FAIL: head mode: the measure's crowd is not said"; fail=1; }
if grep -q "strand contacts" "$tmp/head.err"; then
  echo "FAIL: head mode: a warning about strand contacts, which the mode does not have"; fail=1
fi
grep -q "too dense a crowd for the strand contacts" "$tmp/strands.err" ||
  { echo "FAIL: strands mode: the contacts' crowd is not said"; fail=1; }
exit $fail
