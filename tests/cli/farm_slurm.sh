#!/usr/bin/env bash
# scripts/farm/shot.sh on a Slurm of the test's own (scripts/farm/local_slurm.sh: munge, slurmctld,
# slurmd, a folder and port of its own, stopped at the end): the default preset (fewer strands, a
# small frame), 60 frames in 4 chunks: one bake, an array of 4 render chunks after it, a join; chunk
# 2 requeued while it is part-way through its frames. Every frame and the video are the same bytes
# as one process's, the requeued chunk ran twice. Skipped (ctest's skip status, 77) only where
# slurmctld cannot be installed, saying so.
set -u
bin=$1
src=$2
tmp=$(mktemp -d)
export CSM_SLURM_DIR=$tmp/slurm CSM_SLURM_PORT=$((16817 + $$ % 2000 * 2))
cleanup() { bash "$src/scripts/farm/local_slurm.sh" stop; rm -rf "$tmp"; }
trap cleanup EXIT
started=$(bash "$src/scripts/farm/local_slurm.sh" start)
status=$?
if [ $status -ne 0 ]; then
  if [ $status -eq 3 ] && ! command -v slurmctld >/dev/null; then
    echo "SKIP: slurmctld cannot be installed here (local_slurm.sh start: exit 3)"
    exit 77
  fi
  echo "FAIL: local_slurm.sh start: exit $status"; cat "$CSM_SLURM_DIR"/log/* 2>/dev/null; exit 1
fi
eval "$started"
echo "slurm up: $SLURM_CONF"
args=(--size 96x64 --set hairstyle.strands=300 --quiet)

# One process: the reference frames and video.
"$bin" --headless --frames 60 "${args[@]}" --out "$tmp/one" --video "$tmp/one.mp4" ||
  { echo "FAIL: the one-process run"; exit 1; }

# The shot, waited for in the background; chunk 2 requeued part-way.
bash "$src/scripts/farm/shot.sh" default --frames 60 --chunks 4 --out "$tmp/shot" --bin "$bin" \
  --timeout 600 -- "${args[@]}" >"$tmp/shot.out" 2>&1 &
shot=$!
render=""
for _ in $(seq 600); do
  render=$(grep -o 'render=[0-9]*' "$tmp/shot.out" 2>/dev/null | cut -d= -f2)
  [ -n "$render" ] && break
  sleep 0.1
done
[ -n "$render" ] || { echo "FAIL: shot.sh printed no job ids"; cat "$tmp/shot.out"; exit 1; }
requeued=0
for _ in $(seq 1200); do
  if scontrol show job "${render}_2" 2>/dev/null | grep -q 'JobState=RUNNING' &&
     [ -f "$tmp/shot/frames/frame_00016.png" ]; then
    if [ -f "$tmp/shot/frames/frame_00030.png" ]; then break; fi  # the chunk ended first
    scontrol requeue "${render}_2" && requeued=1
    # Slurm holds a requeued task a couple of minutes (Reason=BeginTime); once it is held, it
    # may start again now. Until it runs again (or 30 s).
    pending=0
    for _ in $(seq 300); do
      st=$(scontrol show job "${render}_2" 2>/dev/null)
      if grep -q 'JobState=PENDING' <<<"$st"; then
        pending=1
        grep -q 'Reason=BeginTime' <<<"$st" &&
          scontrol update JobId="${render}_2" StartTime=now 2>/dev/null
      elif [ $pending -eq 1 ]; then
        break
      fi
      sleep 0.1
    done
    break
  fi
  sleep 0.05
done
wait $shot
status=$?
cat "$tmp/shot.out"
fail=0
[ $status -eq 0 ] || { echo "FAIL: shot.sh exit $status"; cat "$tmp"/shot/logs/*; fail=1; }
[ $requeued -eq 1 ] || { echo "FAIL: chunk 2 was not caught part-way to requeue it"; fail=1; }
grep -q "attempt 2" "$tmp/shot/logs/render_2.log" ||
  { echo "FAIL: chunk 2 did not run again"; cat "$tmp/shot/logs/render_2.log"; fail=1; }
n=0
for f in "$tmp"/one/*.png; do
  n=$((n + 1))
  cmp -s "$f" "$tmp/shot/frames/$(basename "$f")" || { echo "FAIL: $(basename "$f") differs"; fail=1; }
done
[ "$(ls "$tmp/shot/frames" | grep -c '\.png$')" -eq 60 ] || { echo "FAIL: not 60 frames"; fail=1; }
cmp "$tmp/one.mp4" "$tmp/shot/shot.mp4" || { echo "FAIL: the video differs"; fail=1; }
echo "$n frames compared; the video $(stat -c %s "$tmp/shot/shot.mp4") bytes"
[ $fail -eq 0 ] && echo ok
exit $fail
