#!/usr/bin/env bash
# Headless ms per frame of a preset, per binary, the binaries alternated in one run: each
# binary runs the preset for A and for B frames, and (wall(B) - wall(A)) / (B - A) is its cost
# per frame without start-up (context, shaders, growing the groom). Two modes: simulation
# only (--no-render), and the capture path (--out: every frame drawn off-screen and written
# as a PNG to a temporary folder).
#   scripts/bench_headless.sh PRESET A B BIN...
# OLD_PRESETS=DIR OLD_BIN=BIN: that binary reads its presets from DIR. MODES: a subset.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
preset=$1 a=$2 b=$3
shift 3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
wall() {  # wall BIN FILE FRAMES ARGS...
  local bin=$1 file=$2 frames=$3
  shift 3
  local t0 t1
  t0=$(date +%s.%N)
  "$bin" "$file" --headless --frames "$frames" --quiet "$@" >/dev/null 2>&1
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }'
}
echo "Load before: $(uptime | sed 's/.*load average: //')"
echo
echo "| preset | mode | binary | wall $a frames (s) | wall $b frames (s) | ms / frame |"
echo "|---|---|---|---|---|---|"
for mode in ${MODES:-no-render capture}; do
  args=(--no-render)
  [ "$mode" != capture ] || args=(--out "$tmp/frames")
  for bin in "$@"; do
    file="$root/presets/$preset.json"
    [ "$bin" != "${OLD_BIN:-}" ] || file="$OLD_PRESETS/$preset.json"
    wa=$(wall "$bin" "$file" "$a" "${args[@]}")
    wb=$(wall "$bin" "$file" "$b" "${args[@]}")
    per=$(awk -v wa="$wa" -v wb="$wb" -v a="$a" -v b="$b" 'BEGIN { print 1000 * (wb - wa) / (b - a) }')
    printf "| %s | %s | %s | %.2f | %.2f | %.0f |\n" "$preset" "$mode" "$bin" "$wa" "$wb" "$per"
  done
done
echo
echo "Load after: $(uptime | sed 's/.*load average: //')"
