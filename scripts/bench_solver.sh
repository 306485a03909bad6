#!/usr/bin/env bash
# The GPU solver (llvmpipe where there is no GPU) against the CPU reference on the paper's two
# scenes, then how a GPU frame grows with the strand count and with the stiffness window w.
# Strand counts 1k to 100k, the step alone (head collisions) and with hair-hair collisions;
# every count grows on the same scalp, so the hair gets denser and the contact pass grows
# faster than the count (pairs per segment grow with the density).
# Prints a Markdown table: ms per frame (all substeps and the collision pass), split by stage.
#   scripts/bench_solver.sh [BIN] [FRAMES]
# FRAMES (default 4) per row; big rows run fewer. Means include the first frame, which on
# llvmpipe also compiles the shaders (a few hundred ms once).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/app/csmhair"}
frames=${2:-4}
fig1="$root/presets/paper_fig1_straight.json"
fig3="$root/presets/paper_fig3_curly.json"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

row() {  # row LABEL SOLVER PRESET FRAMES ARGS...
  local label=$1 solver=$2 preset=$3 n=$4
  shift 4
  "$bin" "$preset" --headless --no-render --quiet --solver "$solver" --frames "$n" \
    --metrics "$tmp/m.json" "$@"
  python3 - "$tmp/m.json" "$label" "$n" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
s = m["ms"]["stages"]
frame = m["ms"]["sim_mean"]
steps = 1000.0 * m["substeps"] / frame
dev = m.get("device", "?").split(" (")[0]
print(f"| {sys.argv[2]:<30} | {dev:<9} | {m['particles']:>9} | {sys.argv[3]:>2} | {frame:9.1f} | "
      f"{steps:6.1f} | {s.get('integrate', 0):8.1f} | {s.get('shape_matching', 0):8.1f} | "
      f"{s.get('strain_limiting', 0):8.1f} | {s.get('grid', 0):7.1f} | "
      f"{s.get('contacts', 0):8.1f} | {m['accuracy']['hair_contacts']:>8} |")
PY
}

# The machine may be shared: the load average before and after, to judge the numbers by.
echo "Load before: $(uptime | sed 's/.*load average: //')"
echo
echo "| scene                          | device    | particles | fr |  ms/frame | steps/s | integrate | shape m. | strain | grid | contacts | contact pairs |"
echo "|--------------------------------|-----------|-----------|----|-----------|---------|----------|----------|--------|---------|----------|----------|"
row "Fig. 1, full collisions"        gpu "$fig1" "$frames"
row "Fig. 1, full collisions"        cpu "$fig1" 2
row "Fig. 1, head only"              gpu "$fig1" "$frames" --set collision.mode=head
row "Fig. 1, head only"              cpu "$fig1" 2 --set collision.mode=head
row "Fig. 3, full collisions"        gpu "$fig3" 2
row "Fig. 3, full collisions"        cpu "$fig3" 2
for strands in 1000 3000 10000 30000 100000; do
  n=$frames
  [ "$strands" -ge 30000 ] && n=2
  row "Fig. 1, head only, ${strands} str." gpu "$fig1" "$n" --set collision.mode=head \
    --set hairstyle.strands=$strands
done
for strands in 1000 3000 10000 30000 100000; do
  n=$frames
  [ "$strands" -ge 30000 ] && n=2
  row "Fig. 1, full, ${strands} str." gpu "$fig1" "$n" --set hairstyle.strands=$strands
done
for w in 1 2 4 8 15; do
  row "Fig. 1, head only, w=$w" gpu "$fig1" "$frames" --set collision.mode=head \
    --set sim.stiffness_model=paper --set sim.stiffness_window=$w
done
echo
echo "Load after: $(uptime | sed 's/.*load average: //')"
