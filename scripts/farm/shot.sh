#!/usr/bin/env bash
# A shot on a Slurm cluster: simulated once into a cache, drawn in chunks, joined into a video.
#   bash scripts/farm/shot.sh PRESET --frames N --chunks K --out DIR [options] [-- csmhair args]
# submits three jobs:
#   bake    csmhair PRESET --headless --frames N --bake DIR/cache ARGS     (one task; a requeued
#           bake goes on from its last frame with --resume)
#   render  an array of K tasks after the bake (--dependency=afterok): task i draws its chunk of
#           the frames, csmhair --from-cache DIR/cache --frames A-B --out DIR/frames ARGS
#           (idempotent: each PNG is written whole, a rerun rewrites the same bytes)
#   join    after every chunk: DIR/frames/frame_%05d.png into DIR/shot.mp4, encoded as
#           csmhair --video encodes (the same bytes as one process's video of the same frames)
# then waits for them and reports, or with --no-wait prints the three job ids and returns.
# Logs go to DIR/logs/. A chunk that fails at run time (exit 1, or killed) requeues itself up to
# --retries times (Slurm's requeue; a requeued task starts again and rewrites its frames); bad
# input (exit 2, e.g. a bake that did not finish) fails at once, saying why in its log.
#
# Options:
#   --partition P     the partition to submit to (default: the cluster's default)
#   --gres G          a generic resource each job asks for, e.g. gpu:1 on GPU nodes
#   --cpus C          cores a task asks for (default 1)
#   --retries R       requeues of a failed chunk (default 2)
#   --bin PATH        the csmhair to run (default: build/app/csmhair of this checkout); it and DIR
#                     must be on a folder every node sees
#   --no-wait         print "bake=ID render=ID join=ID" and return
#   --timeout S       give up waiting after S seconds (default 3600), exit 1
# Every argument after -- goes to each csmhair run (e.g. --size 1920x1080 --set wind.strength=2):
# the bake takes the simulation's, the chunks the render's; a simulation parameter the chunks were
# given differently from the bake is refused by them.
# Exit status: 0 the shot is done (or submitted, --no-wait), 1 a job failed, 2 bad arguments.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }

preset="" frames="" chunks="" out="" partition="" gres="" cpus=1 retries=2 wait=1 timeout=3600
bin="$root/build/app/csmhair"
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --frames) frames=${2:?}; shift 2 ;;
    --chunks) chunks=${2:?}; shift 2 ;;
    --out) out=${2:?}; shift 2 ;;
    --partition) partition=${2:?}; shift 2 ;;
    --gres) gres=${2:?}; shift 2 ;;
    --cpus) cpus=${2:?}; shift 2 ;;
    --retries) retries=${2:?}; shift 2 ;;
    --bin) bin=${2:?}; shift 2 ;;
    --no-wait) wait=0; shift ;;
    --timeout) timeout=${2:?}; shift 2 ;;
    --) shift; args=("$@"); break ;;
    -h|--help) usage ;;
    -*) echo "shot.sh: unknown option $1" >&2; usage ;;
    *) [ -z "$preset" ] || { echo "shot.sh: one preset only ($preset, $1)" >&2; exit 2; }; preset=$1; shift ;;
  esac
done
[ -n "$preset" ] && [ -n "$frames" ] && [ -n "$chunks" ] && [ -n "$out" ] || usage
[[ "$frames" =~ ^[1-9][0-9]*$ ]] || { echo "shot.sh: --frames needs a whole number >= 1" >&2; exit 2; }
[[ "$chunks" =~ ^[1-9][0-9]*$ ]] || { echo "shot.sh: --chunks needs a whole number >= 1" >&2; exit 2; }
[ "$chunks" -le "$frames" ] || { echo "shot.sh: more chunks ($chunks) than frames ($frames)" >&2; exit 2; }
[ -x "$bin" ] || { echo "shot.sh: no csmhair at $bin (build it, or give --bin)" >&2; exit 2; }
command -v sbatch >/dev/null || { echo "shot.sh: no sbatch: not on a Slurm cluster (scripts/farm/local_slurm.sh start makes one here)" >&2; exit 2; }
[ "$preset" = default ] || preset=$(realpath "$preset")
mkdir -p "$out/logs" "$out/frames"
out=$(realpath "$out")
bin=$(realpath "$bin")

# Every job: the partition, the resource, the cores; its script with the values written in.
common=(--parsable -c "$cpus")
[ -z "$partition" ] || common+=(--partition "$partition")
[ -z "$gres" ] || common+=(--gres "$gres")
quoted=$(printf ' %q' "${args[@]+"${args[@]}"}")
presetArg=$([ "$preset" = default ] || printf '%q' "$preset")
every=1
for ((i = 0; i < ${#args[@]}; i++)); do
  [ "${args[$i]}" = --every ] && every=${args[$((i + 1))]}
done

cat >"$out/bake.sh" <<JOB
#!/usr/bin/env bash
# The bake: a requeued one (SLURM_RESTART_COUNT > 0) goes on from its last frame.
set -u
if [ "\${SLURM_RESTART_COUNT:-0}" -gt 0 ] && [ -f "$out/cache/manifest.json" ]; then
  exec "$bin" --headless --bake "$out/cache" --resume --frames $frames$quoted
fi
exec "$bin" $presetArg --headless --frames $frames --bake "$out/cache"$quoted
JOB
cat >"$out/render.sh" <<JOB
#!/usr/bin/env bash
# Chunk SLURM_ARRAY_TASK_ID of $chunks: its frames drawn from the cache.
set -u
i=\${SLURM_ARRAY_TASK_ID:?}
size=\$(( ($frames + $chunks - 1) / $chunks ))
first=\$(( (i - 1) * size + 1 ))
last=\$(( i * size < $frames ? i * size : $frames ))
echo "chunk \$i: frames \$first-\$last (attempt \$(( \${SLURM_RESTART_COUNT:-0} + 1 )))"
"$bin" --headless --from-cache "$out/cache" --frames "\$first-\$last" --out "$out/frames"$quoted
status=\$?
if [ \$status -ne 0 ] && [ \$status -ne 2 ] && [ "\${SLURM_RESTART_COUNT:-0}" -lt $retries ]; then
  echo "chunk \$i: exit \$status; requeued"
  scontrol requeue "\${SLURM_ARRAY_JOB_ID}_\${i}"
  sleep 30  # the requeue ends this task
fi
exit \$status
JOB
cat >"$out/join.sh" <<JOB
#!/usr/bin/env bash
# The frames into a video, as csmhair --video encodes them: the bake's frame rate, rgb24 in,
# yuv420p H.264 at crf 18 out.
set -euo pipefail
rate=\$(python3 -c 'import json,sys; m=json.load(open(sys.argv[1])); print("%.6g" % (1.0 / (m["dt"] * $every)))' "$out/cache/manifest.json")
ffmpeg -y -loglevel error -framerate "\$rate" -i "$out/frames/frame_%05d.png" \\
  -vf "scale=trunc(iw/2)*2:trunc(ih/2)*2" -pix_fmt yuv420p -c:v libx264 -crf 18 "$out/shot.mp4.tmp.mp4"
mv "$out/shot.mp4.tmp.mp4" "$out/shot.mp4"
echo "wrote $out/shot.mp4 (\$(ls "$out/frames" | grep -c '\.png\$') frames at \$rate fps)"
JOB
chmod +x "$out"/{bake,render,join}.sh

bake=$(sbatch "${common[@]}" -J csm-bake --requeue -o "$out/logs/bake.log" --open-mode=append "$out/bake.sh")
render=$(sbatch "${common[@]}" -J csm-render --requeue --array="1-$chunks" \
  --dependency="afterok:$bake" --kill-on-invalid-dep=yes -o "$out/logs/render_%a.log" \
  --open-mode=append "$out/render.sh")
join=$(sbatch "${common[@]}" -J csm-join --dependency="afterok:$render" \
  --kill-on-invalid-dep=yes -o "$out/logs/join.log" "$out/join.sh")
echo "bake=$bake render=$render join=$join"
[ $wait = 1 ] || exit 0

source "$root/scripts/farm/lib.sh"
start=$SECONDS
farm_wait "$timeout" "$out/logs" bake="$bake" render="$render" join="$join" || exit 1
echo "shot.sh: done in $((SECONDS - start)) s: $out/frames/ ($(ls "$out/frames" | grep -c '\.png$') frames), $out/shot.mp4"
