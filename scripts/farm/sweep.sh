#!/usr/bin/env bash
# A parameter sweep on a Slurm cluster, and its contact sheet.
#   bash scripts/farm/sweep.sh PRESET KEY=V1,V2,... [KEY=V1,V2,...] [options] [-- csmhair args]
# runs every combination of the values (2 keys of 2 and 3 values: 6 variants) as an array job, a
# task a variant: its bake (csmhair PRESET --headless --frames N --bake DIR/NNN/cache --set ...)
# and the frame shown drawn from it (--from-cache --frames F-F --out DIR/NNN); then a job after
# them all draws DIR/sheet.png: that frame of every variant in a grid (a row for each value of
# the first key, a column for each of the rest), each labelled with its values.
# Waits and reports, or with --no-wait prints "sweep=ID sheet=ID" and returns.
#
# Options:
#   --frames N      frames each variant simulates (default 60)
#   --frame F       the frame on the sheet (default N)
#   --out DIR       where the variants and the sheet go (default out/sweep)
#   --size WxH      each cell's size (default 480x270)
#   --partition P, --gres G, --cpus C, --bin PATH, --timeout S: as scripts/farm/shot.sh's
# Exit status: 0 the sheet is drawn (or the jobs submitted), 1 a job failed, 2 bad arguments.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }

preset="" frames=60 frame="" out=out/sweep size=480x270 partition="" gres="" cpus=1 wait=1
timeout=3600 bin="$root/build/app/csmhair"
keys=() args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --frames) frames=${2:?}; shift 2 ;;
    --frame) frame=${2:?}; shift 2 ;;
    --out) out=${2:?}; shift 2 ;;
    --size) size=${2:?}; shift 2 ;;
    --partition) partition=${2:?}; shift 2 ;;
    --gres) gres=${2:?}; shift 2 ;;
    --cpus) cpus=${2:?}; shift 2 ;;
    --bin) bin=${2:?}; shift 2 ;;
    --no-wait) wait=0; shift ;;
    --timeout) timeout=${2:?}; shift 2 ;;
    --) shift; args=("$@"); break ;;
    -h|--help) usage ;;
    -*) echo "sweep.sh: unknown option $1" >&2; usage ;;
    *=*) keys+=("$1"); shift ;;
    *) [ -z "$preset" ] || { echo "sweep.sh: one preset only ($preset, $1)" >&2; exit 2; }; preset=$1; shift ;;
  esac
done
[ -n "$preset" ] && [ ${#keys[@]} -gt 0 ] || usage
frame=${frame:-$frames}
[[ "$frames" =~ ^[1-9][0-9]*$ ]] && [[ "$frame" =~ ^[1-9][0-9]*$ ]] && [ "$frame" -le "$frames" ] ||
  { echo "sweep.sh: --frames N and --frame F need 1 <= F <= N" >&2; exit 2; }
[ -x "$bin" ] || { echo "sweep.sh: no csmhair at $bin (build it, or give --bin)" >&2; exit 2; }
command -v sbatch >/dev/null || { echo "sweep.sh: no sbatch: not on a Slurm cluster (scripts/farm/local_slurm.sh start makes one here)" >&2; exit 2; }
[ "$preset" = default ] || preset=$(realpath "$preset")
mkdir -p "$out/logs"
out=$(realpath "$out")
bin=$(realpath "$bin")

# The variants, a line each: "KEY=V KEY=V ...", every combination, the first key slowest.
python3 - "$out/variants.txt" "${keys[@]}" <<'PY'
import itertools, sys
axes = []
for spec in sys.argv[2:]:
    key, _, values = spec.partition("=")
    vals = [v for v in values.split(",") if v != ""]
    if not key or not vals:
        sys.exit("sweep.sh: %r: needs KEY=V1,V2,..." % spec)
    axes.append([key + "=" + v for v in vals])
with open(sys.argv[1], "w") as f:
    for combo in itertools.product(*axes):
        f.write(" ".join(combo) + "\n")
PY
count=$(wc -l <"$out/variants.txt")
first=${keys[0]#*=}
rows=$(tr ',' '\n' <<<"$first" | grep -c .)
cols=$((count / rows))
# Every csmhair argument, and each variant's --set, written into the jobs' scripts.
quoted=$(printf ' %q' "${args[@]+"${args[@]}"}")
presetArg=$([ "$preset" = default ] || printf '%q' "$preset")

cat >"$out/variant.sh" <<JOB
#!/usr/bin/env bash
# Variant SLURM_ARRAY_TASK_ID: its bake, then frame $frame drawn from it.
set -euo pipefail
i=\${SLURM_ARRAY_TASK_ID:?}
line=\$(sed -n "\${i}p" "$out/variants.txt")
sets=()
for kv in \$line; do sets+=(--set "\$kv"); done
dir=$out/\$(printf '%03d' "\$i")
echo "variant \$i: \$line"
"$bin" $presetArg --headless --frames $frames --bake "\$dir/cache" "\${sets[@]}"$quoted
"$bin" --headless --from-cache "\$dir/cache" --frames $frame-$frame --size $size --out "\$dir" \\
  "\${sets[@]}"$quoted
JOB
cat >"$out/sheet.sh" <<JOB
#!/usr/bin/env bash
# The contact sheet: frame $frame of each variant with its values under it, $rows rows of $cols.
set -euo pipefail
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
fontArg=\$([ -f "\$font" ] && echo ":fontfile=\$font" || true)
mkdir -p "$out/cells"
for i in \$(seq $count); do
  n=\$(printf '%03d' "\$i")
  sed -n "\${i}p" "$out/variants.txt" | tr ' ' '\\n' >"$out/cells/\$n.txt"
  lines=\$(wc -l <"$out/cells/\$n.txt")
  ffmpeg -y -loglevel error -i "$out/\$n/frame_\$(printf '%05d' $frame).png" \\
    -vf "pad=iw:ih+8+20*\$lines:0:0:color=white,drawtext=textfile=$out/cells/\$n.txt\$fontArg:fontsize=15:line_spacing=4:fontcolor=black:x=8:y=h-4-20*\$lines" \\
    "$out/cells/\$n.png"
done
ffmpeg -y -loglevel error -framerate 1 -i "$out/cells/%03d.png" \\
  -vf "tile=${cols}x${rows}:padding=4:margin=4:color=white" -frames:v 1 "$out/sheet.tmp.png"
mv "$out/sheet.tmp.png" "$out/sheet.png"
echo "wrote $out/sheet.png ($count variants, $rows x $cols)"
JOB
chmod +x "$out"/{variant,sheet}.sh

common=(--parsable -c "$cpus")
[ -z "$partition" ] || common+=(--partition "$partition")
[ -z "$gres" ] || common+=(--gres "$gres")
sweep=$(sbatch "${common[@]}" -J csm-sweep --requeue --array="1-$count" \
  -o "$out/logs/variant_%a.log" "$out/variant.sh")
sheet=$(sbatch "${common[@]}" -J csm-sheet --dependency="afterok:$sweep" --kill-on-invalid-dep=yes \
  -o "$out/logs/sheet.log" "$out/sheet.sh")
echo "sweep=$sweep sheet=$sheet ($count variants)"
[ $wait = 1 ] || exit 0
source "$root/scripts/farm/lib.sh"
start=$SECONDS
farm_wait "$timeout" "$out/logs" sweep="$sweep" sheet="$sheet" || exit 1
echo "sweep.sh: done in $((SECONDS - start)) s: $out/sheet.png"
