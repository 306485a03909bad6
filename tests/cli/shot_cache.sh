#!/usr/bin/env bash
# A shot's cache (--bake, --from-cache, --resume; app/shot_cache.h), end to end, on both solvers:
# - the same pixels: frames drawn by one process and the same frames drawn from its cache alone
#   (frames 13-18 of 20; with --every 2), the same PNG bytes and names; a guided groom
#   (followers drawn from the cached guides) the same (the GPU solver); the sequence export
#   from the cache the same files; --video the same file;
# - a bake killed with SIGKILL part-way: its complete frames render, and --resume finishes with
#   the same last frame as an uninterrupted bake;
# - refused, each with what is wrong: a simulation parameter --set (a render one is taken), a
#   preset beside the cache, --frames 20-11 and frames beyond the cache, a truncated frame (its
#   byte), a cache of another format version, a groom that is not the one baked.
set -u
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/lib/expect.sh"
# A smaller default scene: the default preset's look (children, shadows), fewer strands.
small=(--size 96x64 --quiet)
strands=(--set hairstyle.strands=400)

same_frames() {  # DIR_A DIR_B WHAT: every PNG of B is A's of the same name
  local n=0 f
  for f in "$2"/*.png; do
    n=$((n + 1))
    cmp -s "$f" "$1/$(basename "$f")" || { echo "FAIL: $3: $(basename "$f") differs"; fail=1; }
  done
  echo "$3: $n frames compared"
}

for solver in cpu gpu; do
  d=$tmp/$solver
  "$bin" --headless --solver $solver "${small[@]}" "${strands[@]}" --frames 20 --out "$d/one" --bake "$d/cache" \
    --export-hair-sequence "$d/seq_one" || { echo "FAIL: $solver bake"; exit 1; }
  "$bin" --headless --from-cache "$d/cache" "${small[@]}" "${strands[@]}" --frames 13-18 --out "$d/part" \
    --export-hair-sequence "$d/seq_part" || { echo "FAIL: $solver from cache"; exit 1; }
  [ "$(ls "$d/part" | tr '\n' ' ')" = "$(seq -f 'frame_%05g.png' 13 18 | tr '\n' ' ')" ] ||
    { echo "FAIL: $solver: names drawn from the cache: $(ls "$d/part")"; fail=1; }
  same_frames "$d/one" "$d/part" "$solver: frames 13-18 from the cache"
  for f in "$d"/seq_part/*.hair; do
    cmp -s "$f" "$d/seq_one/$(basename "$f")" || { echo "FAIL: $solver: $f"; fail=1; }
  done
  # --every 2: frame_00007 is frame 14, as in the run that kept every second frame.
  "$bin" --headless --from-cache "$d/cache" "${small[@]}" --frames 13-18 --every 2 \
    --out "$d/every2" || fail=1
  [ "$(ls "$d/every2" | tr '\n' ' ')" = "$(seq -f 'frame_%05g.png' 7 9 | tr '\n' ' ')" ] ||
    { echo "FAIL: $solver: --every 2 names: $(ls "$d/every2")"; fail=1; }
  cmp -s "$d/every2/frame_00007.png" "$d/one/frame_00014.png" ||
    { echo "FAIL: $solver: --every 2: frame_00007 is not frame 14"; fail=1; }

  # --video from the cache: the same file as the simulating run's of the same frames.
  if [ $solver = cpu ]; then
    "$bin" --headless --solver $solver "${small[@]}" "${strands[@]}" --frames 8 --video "$d/one.mp4" ||
      fail=1
    "$bin" --headless --from-cache "$d/cache" "${small[@]}" "${strands[@]}" --frames 1-8 \
      --video "$d/cache.mp4" || fail=1
    cmp "$d/one.mp4" "$d/cache.mp4" || { echo "FAIL: --video from the cache differs"; fail=1; }
  fi

  # A guided groom: the followers are drawn from the cached guides (on the GPU solver; both in
  # scripts/bench_cache.sh).
  [ $solver = gpu ] || continue
  guided=(--set hairstyle.strands=800 --set hairstyle.guides=80)
  "$bin" --headless --solver $solver "${small[@]}" "${guided[@]}" --frames 8 --out "$d/g_one" \
    --bake "$d/g_cache" || fail=1
  "$bin" --headless --from-cache "$d/g_cache" "${small[@]}" "${guided[@]}" --frames 6-8 \
    --out "$d/g_part" || fail=1
  same_frames "$d/g_one" "$d/g_part" "$solver: a guided groom from the cache"
done

# Killed part-way: what it holds renders, --resume finishes it as an uninterrupted bake.
k=$tmp/killed
"$bin" --headless --no-render --solver gpu --quiet --set hairstyle.strands=400 --frames 20 \
  --bake "$k" &
pid=$!
for _ in $(seq 600); do
  [ "$(ls "$k/frames" 2>/dev/null | grep -c '\.bin$')" -ge 8 ] && break
  sleep 0.05
done
kill -9 $pid 2>/dev/null
wait $pid 2>/dev/null
held=$(ls "$k/frames" | grep -c '^frame_[0-9]*\.bin$')
echo "killed with $held frames written"
if [ "$held" -ge 20 ]; then
  echo "FAIL: the bake ended before it was killed"; fail=1
fi
expect 0 "" -- --headless --from-cache "$k" --frames "1-$held" --size 64x36 --quiet --out "$tmp/k_out"
expect 2 "holds frames 1-$held of the bake's 20 (its bake stopped: --bake DIR --resume goes on)" -- \
  --headless --from-cache "$k" --frames 1-20 --size 64x36 --quiet --out "$tmp/k_out"
expect 0 "the cache holds frames 1-$held of 20; going on" -- --headless --bake "$k" --resume
cmp "$k/frames/frame_00020.bin" "$tmp/gpu/cache/frames/frame_00020.bin" ||
  { echo "FAIL: the resumed bake's last frame is not the uninterrupted bake's"; fail=1; }

# Refused, each saying what is wrong.
c=$tmp/cpu/cache
expect 2 "--set wind.strength=9: a simulation parameter (the cache $c was baked with wind.strength=" -- \
  --headless --from-cache "$c" --set wind.strength=9 --frames 1-2 --out "$tmp/r"
expect 0 "" -- --headless --from-cache "$c" --set render.background=[0,0,0] --set hairstyle.strands=400 \
  --frames 2-2 --size 64x36 --out "$tmp/r"
expect 2 "a cache draws the preset it was baked with" -- \
  --headless --from-cache "$c" "$(dirname "$0")/../../presets/default.json" --frames 1-2
expect 2 "--frames 20-11: the first frame is after the last" -- --headless --from-cache "$c" --frames 20-11
expect 2 "--frames 0-3: frames count from 1" -- --headless --from-cache "$c" --frames 0-3
expect 2 "--frames 15-21: the cache $c holds frames 1-20" -- --headless --from-cache "$c" --frames 15-21
expect 2 "--resume goes on with a bake" -- --headless --resume
expect 2 "$tmp/none: not a shot's cache" -- --headless --from-cache "$tmp/none" --frames 1-2
touch "$tmp/a_file"
expect 1 "--bake $tmp/a_file: a file, not a folder" -- --headless --no-render --frames 1 \
  --set hairstyle.strands=20 --bake "$tmp/a_file"
truncate -s 1000 "$c/frames/frame_00015.bin"
expect 2 "holds frames 1-14 of the bake's 20" -- --headless --from-cache "$c" --frames 11-20 --out "$tmp/r"
cp "$tmp/cpu/cache/frames/frame_00016.bin" "$c/frames/frame_00015.bin"
expect 2 "frame_00015.bin: byte 16: the file of frame 16 in the place of frame 15" -- --headless --from-cache "$c" --frames 15-15 --out "$tmp/r" \
  --size 64x36
sed -i 's/"csmhair_cache": 1/"csmhair_cache": 7/' "$c/manifest.json"
expect 2 "a cache of format version 7; this csmhair reads 1: bake it again" -- \
  --headless --from-cache "$c" --frames 1-2
g=$tmp/gpu/g_cache
sed -i 's/"hash": "[0-9a-f]*"/"hash": "0123456789abcdef"/' "$g/manifest.json"
expect 2 "is not the one baked" -- --headless --from-cache "$g" --frames 1-2 --size 64x36 --out "$tmp/r"
[ $fail -eq 0 ] && echo ok
exit $fail
