#!/usr/bin/env bash
# A production-size groom simulated through guides, against the same groom cut to its guides:
#   1. a 100,000-strand, 32-points-a-strand groom from the generator (the default hairstyle),
#      written as cyHair at rest (every strand as drawn);
#   2. the same groom cut to its 4,000 guides (--export-guides): what is simulated;
#   3. each opened with the solver SOLVER (default gpu: on llvmpipe its buffers are process
#      memory) for FRAMES frames drawn at 1280x720, render.children 0: start-up (the groom read,
#      fitted, the guides chosen and bound, the solver reset), the wall time to the first frame
#      stepped, peak RSS, sim ms a frame, render ms by pass, strands simulated and drawn.
#   scripts/production_groom.sh [BIN] [FRAMES] [KEEP_DIR]
# STRANDS and GUIDES change the sizes (default 100000 and 4000). STARTUP_RUNS (default 3): the
# pair is opened again that many times, --frames 0 and nothing drawn but the context made as for
# the drawn runs, alternated, for the start-up ratio's median (one run's start-up on a shared
# machine moves by 20 %).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/app/csmhair"}
frames=${2:-5}
strands=${STRANDS:-100000}
guides=${GUIDES:-4000}
solver=${SOLVER:-gpu}
if [ -n "${3:-}" ]; then
  tmp=$3
  mkdir -p "$tmp"
else
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
fi
grow=(--headless --no-render --quiet --solver cpu --frames 0 --set hairstyle.strands="$strands"
      --set hairstyle.particles_per_strand=32 --set hairstyle.guides="$guides")
"$bin" "${grow[@]}" --export-hair "$tmp/groom.hair"
"$bin" "${grow[@]}" --export-guides --export-hair "$tmp/guides.hair"
echo "Load before: $(uptime | sed 's/.*load average: //')"
for name in groom guides; do
  /usr/bin/time -f "%e %M" -o "$tmp/$name.time" "$bin" --headless --quiet --solver "$solver" \
    --frames "$frames" --size 1280x720 --out "$tmp/frames_$name" --metrics "$tmp/$name.json" \
    --set hairstyle.file="$tmp/$name.hair" --set hairstyle.strands="$strands" \
    --set hairstyle.guides="$guides" --set render.children=0
  rm -rf "$tmp/frames_$name"
done
for r in $(seq 1 "${STARTUP_RUNS:-3}"); do
  for name in groom guides; do
    "$bin" --headless --quiet --solver "$solver" --frames 0 --size 1280x720 \
      --metrics "$tmp/$name.start$r.json" --set hairstyle.file="$tmp/$name.hair" \
      --set hairstyle.strands="$strands" --set hairstyle.guides="$guides" --set render.children=0
  done
done
echo "Load after: $(uptime | sed 's/.*load average: //')"
/usr/bin/python3 - "$tmp" "$frames" "${STARTUP_RUNS:-3}" <<'PY'
import json, statistics, sys
tmp, frames, runs = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
stages = ["followers", "strands", "shadow", "head", "hair", "post"]
print()
print("| groom | strands simulated | drawn | start-up s | peak RSS MB | sim ms/frame | render ms | "
      + " | ".join(stages) + " | wall s |")
print("|---|---|---|---|---|---|---|" + "---|" * len(stages) + "---|")
rows = {}
for name in ("groom", "guides"):
    m = json.load(open(f"{tmp}/{name}.json"))
    wall, rss_kb = open(f"{tmp}/{name}.time").read().split()[-2:]
    ms = m["ms"]
    rs = ms.get("render_stages", {})
    rows[name] = (m["startup_s"], int(rss_kb) / 1024, ms["sim_mean"], ms.get("render_mean", 0))
    print(f"| {name} | {m['strands']:,} | {m['groom_strands']:,} | {m['startup_s']:.2f} | "
          f"{int(rss_kb) / 1024:.0f} | {ms['sim_mean']:.1f} | {ms.get('render_mean', 0):.0f} | "
          + " | ".join(f"{rs.get(s, 0):.1f}" for s in stages) + f" | {float(wall):.1f} |")
g, c = rows["groom"], rows["guides"]
if runs > 0:
    start = {n: [json.load(open(f"{tmp}/{n}.start{r}.json"))["startup_s"] for r in range(1, runs + 1)]
             for n in ("groom", "guides")}
    ratios = [a / b for a, b in zip(start["groom"], start["guides"])]
    print()
    print("Start-up, " + str(runs) + " more runs each, alternated: groom "
          + ", ".join(f"{v:.2f}" for v in start["groom"]) + " s; guides "
          + ", ".join(f"{v:.2f}" for v in start["guides"]) + " s; ratios "
          + ", ".join(f"{v:.2f}" for v in ratios) + f"; median {statistics.median(ratios):.2f}x")
print()
print(f"Against the guides alone: start-up {g[0] / c[0]:.2f}x, peak RSS {g[1] / c[1]:.2f}x, "
      f"sim ms {g[2] / c[2]:.2f}x, render ms {g[3] / max(c[3], 1e-9):.2f}x ({frames} frames)")
PY
