#!/usr/bin/env bash
# --export-hair-sequence DIR: every kept frame as DIR/frame_00001.hair, ... (cyHair), the same
# strands and point counts in each, the last one the same bytes as --export-hair's final
# strands, a second run the same files (deterministic); a folder that cannot be made is an
# error with exit status 1. On both solvers (the GPU one on llvmpipe where there is no GPU).
set -eu
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for solver in cpu gpu; do
  common=(--headless --no-render --solver "$solver" --quiet --set hairstyle.strands=200)
  "$bin" "${common[@]}" --frames 6 --every 2 --export-hair-sequence "$tmp/$solver/seq" \
    --export-hair "$tmp/$solver/last.hair"
  "$bin" "${common[@]}" --frames 6 --every 2 --export-hair-sequence "$tmp/$solver/again"
  ls "$tmp/$solver/seq"
  [ "$(ls "$tmp/$solver/seq")" = "$(printf 'frame_00001.hair\nframe_00002.hair\nframe_00003.hair')" ] ||
    { echo "FAIL: $solver: frames written: $(ls "$tmp/$solver/seq")"; exit 1; }
  cmp "$tmp/$solver/seq/frame_00003.hair" "$tmp/$solver/last.hair" ||
    { echo "FAIL: $solver: the last frame is not the final strands"; exit 1; }
  for f in frame_00001.hair frame_00002.hair frame_00003.hair; do
    cmp "$tmp/$solver/seq/$f" "$tmp/$solver/again/$f" ||
      { echo "FAIL: $solver: $f differs between two runs"; exit 1; }
  done
  python3 - "$tmp/$solver/seq" <<'PY'
import os, struct, sys
seq = sys.argv[1]
def read(path):
    data = open(path, "rb").read()
    assert data[:4] == b"HAIR", path
    hairs, points, flags = struct.unpack_from("<III", data, 4)
    assert flags & 1 and flags & 2, (path, flags)  # segments and points
    segs = struct.unpack_from("<%dH" % hairs, data, 128)
    pts = struct.unpack_from("<%df" % (3 * points), data, 128 + 2 * hairs)
    return hairs, points, segs, pts
frames = [read(os.path.join(seq, f)) for f in sorted(os.listdir(seq))]
assert all(f[0] == 200 for f in frames), [f[0] for f in frames]
assert all(f[1] == frames[0][1] and f[2] == frames[0][2] for f in frames), "strands differ"
# The hair moves between frames (the default preset nods in a breeze).
moved = max(abs(a - b) for a, b in zip(frames[0][3], frames[2][3]))
print("strands", frames[0][0], "points", frames[0][1], "moved from frame 1 to 3 (m)", moved)
assert moved > 1e-4, moved
PY
done

# A folder that cannot be made: exit 1, saying which.
touch "$tmp/file"
set +e
out=$("$bin" --headless --no-render --solver cpu --quiet --frames 1 \
  --export-hair-sequence "$tmp/file/seq" 2>&1)
status=$?
set -e
echo "$out"
[ "$status" -eq 1 ] || { echo "FAIL: exit $status for a folder that cannot be made"; exit 1; }
grep -q "export-hair-sequence: cannot make the folder $tmp/file/seq" <<<"$out" ||
  { echo "FAIL: no clear message"; exit 1; }
echo ok
