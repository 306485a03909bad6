#!/usr/bin/env bash
# A shot's cache and the farm, measured (docs/BENCHMARKS.md, "A shot on a render farm"):
#   bash scripts/bench_cache.sh BIN [SIZE] [FRAMES]     (default 1280x720, 60 frames)
# 1. The same pixels: the default preset drawn by one process and frames 31-45 drawn alone from
#    its cache, every PNG compared, on both solvers; a guided groom (20,000 strands from 2,000
#    guides) the same, frames 31-40 of 40.
# 2. The costs: the bake's seconds (the simulation and the cache's files), the cache's bytes a
#    frame (a guided groom's guides, and every strand of it simulated), the render's seconds a frame
#    from the cache, and the resume after a SIGKILL.
# 3. The farm: scripts/farm/shot.sh on a local Slurm (scripts/farm/local_slurm.sh), FRAMES frames
#    in 1, 2 and 4 chunks, the shot's wall time each (CHUNKS overrides the list), and the frames
#    compared with one process's.
# PARTS="pixels costs farm" picks the parts.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(realpath "$1")
size=${2:-1280x720}
frames=${3:-60}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
compare() {  # A B: "n of m the same bytes"
  local same=0 n=0 f
  for f in "$2"/*.png; do
    n=$((n + 1))
    cmp -s "$f" "$1/$(basename "$f")" && same=$((same + 1))
  done
  echo "$same of $n"
}
echo "Machine: $(nproc) cores, $(uname -m); load before: $(uptime | sed 's/.*load average: //')"
parts=${PARTS:-pixels costs farm}
part() { [[ " $parts " == *" $1 "* ]]; }
if part pixels; then
echo
echo "## The same pixels ($size)"
echo
echo "| scene | solver | one process: simulate and draw (s) | from the cache: draw the range (s) | PNGs the same bytes |"
echo "|---|---|---|---|---|"
for solver in gpu cpu; do
  for scene in default guided; do
    extra=() n=$frames range=31-45
    if [ $scene = guided ]; then
      extra=(--set hairstyle.strands=20000 --set hairstyle.guides=2000)
      n=40 range=31-40
    fi
    d=$tmp/$solver-$scene
    t0=$(now)
    "$bin" --headless --quiet --solver $solver --size "$size" --frames $n "${extra[@]}" \
      --out "$d/one" --bake "$d/cache"
    t1=$(now)
    "$bin" --headless --quiet --from-cache "$d/cache" --size "$size" --frames $range "${extra[@]}" \
      --out "$d/part"
    t2=$(now)
    echo "| $scene$([ $scene = guided ] && echo ' (20,000 from 2,000 guides)') | $solver | $(secs "$t0" "$t1") | $(secs "$t1" "$t2") ($range) | $(compare "$d/one" "$d/part") |"
  done
done
fi
if part costs; then
echo
echo "## The costs"
echo
echo "| | value |"
echo "|---|---|"
d=$tmp/cost
t0=$(now)
"$bin" --headless --quiet --no-render --frames "$frames"
t1=$(now)
"$bin" --headless --quiet --no-render --frames "$frames" --bake "$d/cache"
t2=$(now)
per=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["frame_bytes"])' "$d/cache/manifest.json")
echo "| default preset, GPU solver: $frames frames simulated, no cache | $(secs "$t0" "$t1") s |"
echo "| the same with --bake (a frame file each, a resume state every 10) | $(secs "$t1" "$t2") s |"
echo "| its cache: bytes a frame (3,000 strands simulated) | $per ($(du -sb "$d/cache" | cut -f1) in all, resume state $(stat -c %s "$d/cache/resume.state")) |"
"$bin" --headless --quiet --no-render --frames 2 --set hairstyle.strands=100000 --set hairstyle.guides=4000 \
  --bake "$d/guided"
"$bin" --headless --quiet --no-render --frames 1 --set hairstyle.strands=20000 --set hairstyle.guides=0 \
  --bake "$d/all20k"
guided=$(python3 -c 'import json,sys; m=json.load(open(sys.argv[1])); g=m["groom"]; print(m["frame_bytes"], g["particles"], 104 + 12 * g["drawn_points"], g["drawn_points"])' "$d/guided/manifest.json")
all=$(python3 -c 'import json,sys; m=json.load(open(sys.argv[1])); print(m["frame_bytes"], m["groom"]["particles"])' "$d/all20k/manifest.json")
read -r gb gp ab ap <<<"$guided"
echo "| 100,000 strands from 4,000 guides: bytes a frame, the guides (what is cached) | $gb ($gp particles) |"
echo "| the same groom's every strand, were they all kept | $ab ($ap points): $(awk -v a="$ab" -v g="$gb" 'BEGIN { printf "%.0f", a / g }') times as many |"
echo "| 20,000 strands, every one simulated: bytes a frame | ${all%% *} (${all##* } particles) |"
t0=$(now)
"$bin" --headless --quiet --from-cache "$d/cache" --size "$size" --frames "1-$frames" --out "$d/frames"
t1=$(now)
echo "| render from the cache, $size, $frames frames | $(secs "$t0" "$t1") s ($(awk -v a="$t0" -v b="$t1" -v n="$frames" 'BEGIN { printf "%.2f", (b - a) / n }') s a frame, start-up included) |"
# Killed part-way, resumed.
k=$tmp/killed
"$bin" --headless --quiet --no-render --frames "$frames" --bake "$k" &
pid=$!
while [ "$(ls "$k/frames" 2>/dev/null | grep -c '\.bin$')" -lt $((frames / 2)) ]; do sleep 0.05; done
kill -9 $pid; wait $pid 2>/dev/null || true
held=$(ls "$k/frames" | grep -c '^frame_[0-9]*\.bin$')
"$bin" --headless --quiet --from-cache "$k" --size 320x180 --frames "1-$held" --out "$k/png"
t0=$(now)
"$bin" --headless --quiet --bake "$k" --resume
t1=$(now)
same=$(cmp -s "$k/frames/frame_$(printf %05d "$frames").bin" "$d/cache/frames/frame_$(printf %05d "$frames").bin" && echo "the same bytes" || echo "DIFFERENT")
echo "| SIGKILL at frame $held: its $held frames drawn; --resume to $frames | $(secs "$t0" "$t1") s; frame $frames $same as the uninterrupted bake's |"
fi
if part farm; then
echo
echo "## The farm: scripts/farm/shot.sh on a local Slurm, $frames frames at $size"
echo
"$bin" --headless --quiet --size "$size" --frames "$frames" --out "$tmp/reference"
started=$(CSM_SLURM_DIR=$tmp/slurm CSM_SLURM_PORT=17817 bash "$root/scripts/farm/local_slurm.sh" start)
eval "$started"
echo "| chunks | shot wall (s) | frames the same as one process's |"
echo "|---|---|---|"
for k in ${CHUNKS:-1 2 4}; do
  t0=$(now)
  bash "$root/scripts/farm/shot.sh" default --frames "$frames" --chunks "$k" --out "$tmp/shot$k" \
    --bin "$bin" -- --size "$size" --quiet >/dev/null
  t1=$(now)
  echo "| $k | $(secs "$t0" "$t1") | $(compare "$tmp/reference" "$tmp/shot$k/frames") (of frames 1-$frames) |"
done
CSM_SLURM_DIR=$tmp/slurm bash "$root/scripts/farm/local_slurm.sh" stop
fi
