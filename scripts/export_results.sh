#!/usr/bin/env bash
# Runs every preset on both solvers headless for N frames (default 60) and keeps what a change
# that should alter nothing must leave alone: the final strands (--export-hair) and the metrics.
#   scripts/export_results.sh CSMHAIR_BINARY OUT_DIR [FRAMES]
# Compare two such folders with scripts/same_results.sh.
set -euo pipefail
bin=$1
out=$2
frames=${3:-60}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
for preset in "$here"/presets/*.json; do
  name=$(basename "$preset" .json)
  for solver in cpu gpu; do
    "$bin" "$preset" --headless --no-render --quiet --frames "$frames" --solver "$solver" \
      --export-hair "$out/$name.$solver.hair" --metrics "$out/$name.$solver.json" ||
      echo "$name.$solver: exit $?" >>"$out/failures.txt"
  done
done
