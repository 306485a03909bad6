#!/usr/bin/env bash
# What a groom costs as it grows: for each strand count in STRANDS (default 1,000 to 100,000), a
# groom of that many strands at 32 points (the default hairstyle from the generator, written as
# cyHair at rest) opened twice with the solver SOLVER (default gpu): with the default guides
# (hairstyle.guides=-1: every strand up to 20,000, 4,000 guides beyond, the rest followers) and
# with every strand simulated (hairstyle.guides=0). Each run: FRAMES frames (default 30) of the
# nodding motion, collision.mode=head, drawn at SIZE (default 1280x720), render.children=0.
# Columns: start-up s (the groom read, fitted, guides chosen and bound, solver reset), peak RSS,
# the solver's buffers, sim and render ms a frame (steady: the first frame left out), the
# followers' pass. A table, the CSV into OUT/scale.csv and, where matplotlib is, the chart
# OUT/scale.png (docs/charts by default). STRANDS, FRAMES, SIZE, SOLVER, RUNS: see below.
#   scripts/bench_scale.sh [BIN] [OUT]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/app/csmhair"}
out=${2:-"$root/docs/charts"}
counts=${STRANDS:-"1000 3000 10000 30000 100000"}
frames=${FRAMES:-30}
size=${SIZE:-1280x720}
solver=${SOLVER:-gpu}
mkdir -p "$out"
# The grooms, frames and the runs' metrics go to a temporary folder; RUNS keeps the metrics
# instead (a sweep cut short keeps the runs before it).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
runs=${RUNS:-$tmp/runs}
mkdir -p "$runs"
echo "Load before: $(uptime | sed 's/.*load average: //')"
for n in $counts; do
  "$bin" --headless --no-render --quiet --solver cpu --frames 0 --set hairstyle.strands="$n" \
    --set hairstyle.particles_per_strand=32 --export-hair "$tmp/groom$n.hair"
  for guides in -1 0; do
    "$bin" --headless --quiet --solver "$solver" --frames "$frames" --size "$size" \
      --out "$tmp/frames" --metrics "$runs/m${n}_$guides.json" --set collision.mode=head \
      --set hairstyle.file="$tmp/groom$n.hair" --set hairstyle.strands="$n" \
      --set hairstyle.guides="$guides" --set render.children=0
    rm -rf "$tmp/frames"
  done
  rm -f "$tmp/groom$n.hair"
done
echo "Load after: $(uptime | sed 's/.*load average: //')"
python=python3
[ -x /usr/bin/python3 ] && python=/usr/bin/python3
"$python" - "$runs" "$out" "$frames" "$size" $counts <<'PY'
import csv, json, os, sys
tmp, out, frames, size = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
counts = [int(n) for n in sys.argv[5:]]
keys = ["device", "strands", "simulated", "guides", "particles", "startup_s", "peak_rss_mb",
        "solver_buffers_mb", "sim_ms", "render_ms", "followers_ms"]
rows = []
for n in counts:
    for guides in (-1, 0):
        m = json.load(open(f"{tmp}/m{n}_{guides}.json"))
        ms, mem = m["ms"], m["memory"]
        rows.append({
            "device": m.get("device", "?"), "strands": m["groom_strands"], "simulated": m["strands"],
            "guides": "default" if guides == -1 else "all",
            "particles": m["particles"], "startup_s": round(m["startup_s"], 3),
            "peak_rss_mb": round(mem["peak_rss_bytes"] / 2**20),
            "solver_buffers_mb": round(mem["solver_buffers_total_bytes"] / 2**20, 1),
            "sim_ms": round(ms.get("sim_steady", ms["sim_mean"]), 3),
            "render_ms": round(ms.get("render_steady", ms.get("render_mean", 0.0)), 3),
            "followers_ms": round(ms.get("render_stages", {}).get("followers", 0.0), 3),
        })
with open(os.path.join(out, "scale.csv"), "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=keys)
    w.writeheader()
    w.writerows(rows)
print()
print(f"{frames} frames a run at {size}, collision.mode=head, render.children=0; ms steady "
      "(the first frame left out)")
print()
print("| strands drawn | simulated | guides | particles | start-up s | peak RSS MB | solver buffers MB "
      "| sim ms | render ms | followers ms |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r['strands']:,} | {r['simulated']:,} | {r['guides']} | {r['particles']:,} | "
          f"{r['startup_s']:.2f} | {r['peak_rss_mb']:,} | {r['solver_buffers_mb']:,.1f} | "
          f"{r['sim_ms']:.2f} | {r['render_ms']:.2f} | {r['followers_ms']:.2f} |")
PY
if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  /usr/bin/python3 "$root/scripts/charts.py" "$out" scale
fi
