#!/usr/bin/env bash
# The head's shape: the mannequin's distance field against the spheres, on a preset, each
# solver, the two shapes alternated ROUNDS times in one run (compare as ratios within it).
#   scripts/bench_head.sh PRESET FRAMES ROUNDS [BIN]
# Simulation: collision.mode=head (no hair-hair, so the head is what differs), --no-render.
# Rendering: the same frames drawn at 1280x720, the renderer's "head" stage (the backdrop and
# the head) and its "shadow" stage (the head's depth from the light is part of it).
# SOLVERS: a subset of "gpu cpu".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
preset=$1 frames=$2 rounds=$3
bin=${4:-$root/build/app/csmhair}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "Load before: $(uptime | sed 's/.*load average: //')"
echo
echo "| round | solver | head shape | sim ms/frame | strain limiting + head (ms/frame) | head penetrations | max strain | render: head stage | shadow stage |"
echo "|---|---|---|---|---|---|---|---|---|"
for round in $(seq "$rounds"); do
  for solver in ${SOLVERS:-gpu cpu}; do
    for shape in spheres sdf; do
      "$bin" "$root/presets/$preset.json" --headless --frames "$frames" --no-render --quiet \
        --solver "$solver" --set collision.mode=head --set "collision.head_shape=$shape" \
        --metrics "$tmp/sim.json" >/dev/null 2>&1
      render="$tmp/none.json"
      if [ "$solver" = gpu ]; then
        "$bin" "$root/presets/$preset.json" --headless --frames "$frames" --every 1 --quiet \
          --set collision.mode=head --set "collision.head_shape=$shape" --out "$tmp/frames" \
          --metrics "$tmp/render.json" >/dev/null 2>&1
        render="$tmp/render.json"
      fi
      /usr/bin/python3 - "$tmp/sim.json" "$render" "$round" "$solver" "$shape" <<'PY'
import json, os, sys
m = json.load(open(sys.argv[1]))
a, ms = m["accuracy"], m["ms"]
head, shadow = "-", "-"
if os.path.exists(sys.argv[2]):
    st = json.load(open(sys.argv[2]))["ms"].get("render_stages", {})
    head, shadow = f"{st.get('head', 0):.1f}", f"{st.get('shadow', 0):.1f}"
print(f"| {sys.argv[3]} | {sys.argv[4]} | {sys.argv[5]} | {ms['sim_mean']:.1f} | "
      f"{ms['stages'].get('strain_limiting', 0):.1f} | {a['head_penetrations']} | "
      f"{a['max_strain']:.4f} | {head} | {shadow} |")
PY
    done
  done
done
