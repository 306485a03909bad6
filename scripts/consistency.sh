#!/usr/bin/env bash
# Does the hairstyle stay the same when settings that should not change it change?
# Runs the default preset (CPU solver, 300 strands, head still, no wind) for 2 s with the
# default settings and with each change below, exports the strands, and prints how far the
# tips moved from the default run (mean / max, mm). Several binaries in one run compare
# builds side by side (e.g. before and after a change).
#   scripts/consistency.sh [BIN...]      (default: build/app/csmhair)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -gt 0 ] || set -- "$root/build/app/csmhair"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
seconds=2
frames=$((seconds * 60))
base=(--headless --no-render --quiet --solver cpu --frames "$frames"
      --set hairstyle.strands=300 --set head.motion=none --set wind.strength=0)
variants=(
  "default|"
  "4 -> 8 substeps|--set sim.substeps=8"
  "4 -> 16 substeps|--set sim.substeps=16"
  "segment length 2 -> 1 cm, at most 16 particles|--set hairstyle.segment_length=0.01"
  "segment length 2 -> 1 cm (twice the particles)|--set hairstyle.segment_length=0.01 --set hairstyle.max_particles=32"
  "density 1e-4 -> 5e-6 kg/m|--set sim.density=5e-6"
  "density 1e-4 -> 1e-2 kg/m|--set sim.density=1e-2"
)
compare() {  # compare A.hair B.hair -> "mean / max" of tip distances in mm
  python3 - "$1" "$2" <<'PY'
import struct, sys, math
def tips(path):
    b = open(path, "rb").read()
    n, pts, arrays, dseg = struct.unpack_from("<4I", b, 4)
    off = 128
    segs = [dseg] * n
    if arrays & 1:
        segs = list(struct.unpack_from(f"<{n}H", b, off)); off += 2 * n
    p = struct.unpack_from(f"<{3 * pts}f", b, off)
    out, k = [], 0
    for s in segs:
        k += s + 1
        out.append(p[3 * (k - 1): 3 * k])
    return out
a, b = tips(sys.argv[1]), tips(sys.argv[2])
d = [1000 * math.dist(x, y) for x, y in zip(a, b)]
print(f"{sum(d) / len(d):.1f} / {max(d):.0f}")
PY
}
for bin in "$@"; do
  echo "$bin"
  echo "| change from the default | tips move, mean / max (mm) |"
  echo "|---|---|"
  i=0
  for v in "${variants[@]}"; do
    label=${v%%|*}
    args=${v#*|}
    # shellcheck disable=SC2086
    "$bin" "${base[@]}" $args --export-hair "$tmp/$i.hair"
    [ $i -eq 0 ] || echo "| $label | $(compare "$tmp/0.hair" "$tmp/$i.hair") |"
    i=$((i + 1))
  done
  echo
done
