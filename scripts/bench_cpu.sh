#!/usr/bin/env bash
# The CPU reference solver's ms per step on the paper's Fig. 1 scene (10,000 strands x 16
# particles), and how a step grows with the stiffness window w (prefix sums: it should not; the
# paper stiffness model, whose window counts particles).
#   scripts/bench_cpu.sh [BIN] [FRAMES]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/app/csmhair"}
frames=${2:-6}
preset="$root/presets/paper_fig1_straight.json"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
row() {  # row LABEL ARGS...
  local label=$1
  shift
  "$bin" "$preset" --headless --no-render --quiet --solver cpu --frames "$frames" \
    --metrics "$tmp/m.json" "$@"
  python3 - "$tmp/m.json" "$label" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
s = m["ms"]["stages"]
n = m["substeps"]
step = m["ms"]["sim_mean"] / n
print(f"| {sys.argv[2]:<28} | {step:9.1f} | {s.get('integrate', 0) / n:9.1f} | "
      f"{s.get('shape_matching', 0) / n:9.1f} | {s.get('strain_limiting', 0) / n:9.1f} | "
      f"{s.get('contacts', 0):9.1f} |")
PY
}
echo "| scene ($frames frames)               |   ms/step | integrate | shape match | strain | contacts/frame |"
echo "|------------------------------|-----------|-----------|-------------|--------|----------------|"
row "Fig. 1, collisions full"
row "Fig. 1, collisions head" --set collision.mode=head
for w in 1 2 4 8 15; do
  row "Fig. 1, head, w=$w" --set collision.mode=head --set sim.stiffness_model=paper \
    --set sim.stiffness_window=$w
done
