#!/usr/bin/env bash
# The window's responsiveness under Xvfb (llvmpipe where there is no GPU): the wall time
# between UI frames (mean and 95th percentile), and the simulation's speed (its frame time,
# and the wall time the run took to simulate FRAMES frames), for the default preset and the
# paper's Fig. 1, per binary, the binaries alternated in one run.
#   [FIG1_FRAMES=N] [PRESETS="default ..."] scripts/bench_window.sh [FRAMES] BIN...
# PRESETS: names under presets/, or paths to preset files (any name with a slash).
# FIG1_FRAMES: frames for Fig. 1 (default FRAMES; its frames cost seconds each on llvmpipe).
# --exit-after FRAMES: the window runs until FRAMES frames are simulated (a build from before
# the simulation thread ran one simulated frame per UI frame).
# A binary reports through --metrics (ms.ui_mean, ms.ui_p95, ms.sim_mean); a build from
# before the frame driver prints "ui mean .. ms, ui p95 .. ms" instead (a measurement patch).
# OLD_PRESETS=DIR OLD_BIN=BIN: that binary reads its presets from DIR (presets written for a
# later build hold keys an older one refuses, and it would show the built-in scene instead).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
frames=${1:-40}
shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "Load before: $(uptime | sed 's/.*load average: //')"
echo
echo "| preset | binary | sim frames | wall (s) | wall / sim frame (ms) | sim step (ms) | UI frames | ui mean (ms) | ui p95 (ms) |"
echo "|---|---|---|---|---|---|---|---|---|"
for preset in ${PRESETS:-default paper_fig1_straight}; do
  n=$frames
  [ "$preset" != paper_fig1_straight ] || n=${FIG1_FRAMES:-$frames}
  for bin in "$@"; do
    rm -f "$tmp/m.json"
    file="$root/presets/$preset.json"
    [[ "$preset" != */* ]] || file=$preset  # a path: a preset of one's own
    [ "$bin" != "${OLD_BIN:-}" ] || file="$OLD_PRESETS/$preset.json"
    xvfb-run -a -s "-screen 0 1280x800x24" "$bin" "$file" --size 1280x720 \
      --exit-after "$n" --metrics "$tmp/m.json" >"$tmp/out.txt" 2>&1 || true
    python3 - "$tmp/m.json" "$tmp/out.txt" "$preset" "$bin" "$n" <<'PY'
import json, os, re, sys
metrics, out, preset, binary, n = sys.argv[1:]
text = open(out).read()
mean = p95 = sim = uiframes = wall = None
if os.path.exists(metrics):
    m = json.load(open(metrics))
    ms = m.get("ms", {})
    mean, p95, uiframes = ms.get("ui_mean"), ms.get("ui_p95"), ms.get("ui_frames")
    sim, wall = ms.get("sim_mean"), m.get("wall_seconds")
if p95 is None:
    r = re.search(r"ui mean ([\d.]+) ms, ui p95 ([\d.]+) ms", text)
    if r: mean, p95 = float(r.group(1)), float(r.group(2))
    r = re.search(r"of which the last simulation step ([\d.]+) ms", text)
    if r: sim = float(r.group(1))
    uiframes = int(n) - 1
if wall is None:
    r = re.search(r"frames in ([\d.]+) s", text)
    if r: wall = float(r.group(1))
fmt = lambda v, d=0: "?" if v is None else f"{v:.{d}f}"
per = None if wall is None else 1000.0 * wall / int(n)
print(f"| {preset} | {binary} | {n} | {fmt(wall, 1)} | {fmt(per)} | {fmt(sim)} | {uiframes} | {fmt(mean)} | {fmt(p95)} |")
if p95 is None: print(text[-2000:], file=sys.stderr)
PY
  done
done
echo
echo "Load after: $(uptime | sed 's/.*load average: //')"
