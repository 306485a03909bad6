#!/usr/bin/env bash
# Render ms by pass with 0 / 4 / 8 / 16 drawn hairs around each simulated strand, two binaries
# alternated in one run: an older one (its render-only strands set by OLD_KEY, default
# hairstyle.follow_count, its presets from OLD_PRESETS) and this build (render.children).
# The default preset at 1280x720, FRAMES frames; each cell the lowest mean of REPS runs (the
# machine is shared: the lowest is the least disturbed). Also the simulation's ms a frame,
# which children must not change. COUNTS: the hairs a guide to run (default "0 4 6 8 16").
#   scripts/bench_children.sh OLD_BIN NEW_BIN [FRAMES] [REPS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$1 new=$2 frames=${3:-8} reps=${4:-3}
old_presets=${OLD_PRESETS:-"$root/presets"}
old_key=${OLD_KEY:-hairstyle.follow_count}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() {  # run LABEL BIN PRESET KEY N
  "$2" "$3" --headless --quiet --frames "$frames" --size 1280x720 --out "$tmp/frames" \
    --metrics "$tmp/$1.$rep.json" --set "$4=$5" >/dev/null 2>&1
  rm -rf "$tmp/frames"
}
echo "Load before: $(uptime | sed 's/.*load average: //')"
for rep in $(seq "$reps"); do
  for n in ${COUNTS:-0 4 6 8 16}; do
    run "old$n" "$old" "$old_presets/default.json" "$old_key" "$n"
    run "new$n" "$new" "$root/presets/default.json" render.children "$n"
  done
done
/usr/bin/python3 - "$tmp" "$reps" ${COUNTS:-0 4 6 8 16} <<'PY'
import glob, json, sys
tmp, reps, counts = sys.argv[1], int(sys.argv[2]), [int(n) for n in sys.argv[3:]]
stages = ["strands", "shadow", "head", "hair", "children", "post"]
print("| binary | hairs a guide | drawn | render ms | " + " | ".join(stages) + " | sim ms |")
print("|---|---|---|---|" + "---|" * len(stages) + "---|")
for label, name in (("old", "before"), ("new", "after")):
    for n in counts:
        runs = [json.load(open(f)) for f in sorted(glob.glob(f"{tmp}/{label}{n}.*.json"))]
        best = lambda key: min(r["ms"].get(key, 0.0) for r in runs)
        cells = [min(r["ms"]["render_stages"].get(s, 0.0) for r in runs) for s in stages]
        drawn = runs[0].get("drawn_strands", 0)
        print(f"| {name} | {n} | {drawn:,} | {best('render_mean'):.0f} | " +
              " | ".join(f"{c:.0f}" for c in cells) + f" | {best('sim_mean'):.1f} |")
print("device:", runs[0].get("gl_renderer", runs[0].get("device")))
PY
