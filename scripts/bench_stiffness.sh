#!/usr/bin/env bash
# What the calibrated stiffness model costs per step against the paper's, at the same
# substeps: the paper's Fig. 1 scene (10,000 strands x 16 particles, head collisions only,
# 4 substeps), both models alternated ROUNDS times in one run; the fastest of each.
# Prints ms per step (frame time / substeps) and the ratio, per solver.
#   scripts/bench_stiffness.sh [BIN] [FRAMES] [ROUNDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/app/csmhair"}
frames=${2:-6}
rounds=${3:-3}
fig1="$root/presets/paper_fig1_straight.json"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

step_ms() {  # step_ms SOLVER ARGS... -> ms per step (the fastest frame / substeps)
  local solver=$1
  shift
  "$bin" "$fig1" --headless --no-render --quiet --solver "$solver" --frames "$frames" \
    --set collision.mode=head --set sim.substeps=4 --set sim.max_substeps=4 \
    --metrics "$tmp/m.json" "$@"
  python3 - "$tmp/m.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
assert m["substeps"] == 4, m["substeps"]
print(f"{m['ms']['sim_min'] / m['substeps']:.2f}")
PY
}

echo "Load before: $(uptime | sed 's/.*load average: //')"
echo
echo "| solver | paper (w = 2, alpha 1): ms/step | calibrated (3.5 cm, B 1.7e-3): ms/step | calibrated / paper |"
echo "|---|---|---|---|"
for solver in cpu gpu; do
  best_p=1e9 best_c=1e9
  for _ in $(seq "$rounds"); do
    p=$(step_ms "$solver" --set sim.stiffness_model=paper --set sim.stiffness_window=2)
    c=$(step_ms "$solver" --set sim.stiffness_model=calibrated)
    best_p=$(python3 -c "print(min($best_p, $p))")
    best_c=$(python3 -c "print(min($best_c, $c))")
  done
  ratio=$(python3 -c "print(f'{$best_c / $best_p:.2f}')")
  echo "| $solver | $best_p | $best_c | $ratio |"
done
echo
echo "Load after: $(uptime | sed 's/.*load average: //')"
