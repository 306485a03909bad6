#!/usr/bin/env bash
# A 50,000-strand groom (a cyHair file) drawn two ways: every strand simulated, against 5,000
# simulated guides each drawn with 9 follow hairs (50,000 drawn). Prints ms per frame for both
# and writes the last frame of each, side by side, to docs/images/follow_*.png.
#   scripts/bench_follow.sh [BIN] [FRAMES] [SOLVER]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/app/csmhair"}
frames=${2:-8}
solver=${3:-gpu}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The groom: the generator's 50k strands at rest, 16 particles each, exported to cyHair.
"$bin" --headless --no-render --quiet --solver cpu --frames 0 \
  --set hairstyle.strands=50000 --set hairstyle.particles_per_strand=16 \
  --set head.motion=none --export-hair "$tmp/groom50k.hair"

common=(--headless --quiet --solver "$solver" --frames "$frames" --every "$frames"
        --size 960x540 --set hairstyle.import_scale=1 --set hairstyle.resample_tolerance=0
        --set collision.mode=head --set wind.strength=3 --set head.motion=none)
"$bin" "$tmp/groom50k.hair" "${common[@]}" --out "$tmp/all" --metrics "$tmp/all.json"
"$bin" "$tmp/groom50k.hair" "${common[@]}" --set hairstyle.strands=5000 \
  --set render.children=9 --out "$tmp/follow" --metrics "$tmp/follow.json"

mkdir -p "$root/docs/images"
cp "$(ls "$tmp"/all/frame_*.png | tail -n 1)" "$root/docs/images/follow_all_simulated.png"
cp "$(ls "$tmp"/follow/frame_*.png | tail -n 1)" "$root/docs/images/follow_guides.png"
python3 - "$tmp/all.json" "$tmp/follow.json" <<'PY'
import json, sys
rows = [("50,000 simulated", json.load(open(sys.argv[1]))),
        ("5,000 guides + 9 follow each", json.load(open(sys.argv[2])))]
print("| groom (50k strands drawn) | simulated strands | particles | sim ms/frame | render ms/frame |")
print("|---|---|---|---|---|")
for name, m in rows:
    print(f"| {name} | {m['strands']} | {m['particles']} | {m['ms']['sim_mean']:.0f} | "
          f"{m['ms'].get('render_mean', 0):.0f} |")
print("device:", rows[0][1].get("device"))
PY
