#!/usr/bin/env bash
# Does the hairstyle stay the same when settings that should not change it change?
# Runs the default preset (CPU solver, 300 strands, head still, no wind) for 2 s with the
# default settings and with each change below, exports the strands, and prints how far the
# tips moved from the default run (mean / median / max, mm; then RMS), and between the pairs
# of changes listed. Several binaries in one run compare
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
  "window 4 -> 2 cm|--set sim.window_length=0.02"
  "window 4 -> 6 cm|--set sim.window_length=0.06"
)
# Pairs of variants compared with each other (indices into the list above), after it.
pairs=("window 2 -> 6 cm|7|8")
compare() {  # compare A.hair B.hair -> "mean / median / max / RMS" of tip distances in mm
  python3 "$root/scripts/hair_tips.py" "$1" "$2"
}
for bin in "$@"; do
  echo "$bin"
  echo "| change from the default | tips move, mean / median / max / RMS (mm) |"
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
  for p in "${pairs[@]}"; do
    IFS='|' read -r label a b <<<"$p"
    echo "| $label | $(compare "$tmp/$a.hair" "$tmp/$b.hair") |"
  done
  echo
done
