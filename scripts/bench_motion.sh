#!/usr/bin/env bash
# Hair on a moving character, measured (docs/BENCHMARKS.md, "Hair on a moving character"):
#   bash scripts/bench_motion.sh BIN [CLIP.bvh ...]
# Each clip (the project's own, scripts/make_clips.py, and any given) on the default preset for
# its length or 6 s, and the same preset's nod in the same run, on each solver (SOLVERS, default
# "cpu gpu"): NaN, max strain, particles in the head and in the torso, the fastest particle against the head's
# peak speed (a root's, and the hair's held rigidly) and what the motion explains, steps a frame and sim ms a frame (the
# ratio to the nod's). A markdown table on stdout.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(realpath "$1")
shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 "$root/scripts/make_clips.py" "$tmp/clips"
clips=("$@")
[ ${#clips[@]} -eq 0 ] && clips=("$tmp"/clips/{walk_cm,run_6ch,turn_mixed,jump,dance_zup,walk_zup_inch,cut}.bvh)
solvers=${SOLVERS:-cpu gpu}
echo "| clip | solver | frames | nan | max strain | in head | in torso | max speed m/s | root peak m/s | rigid peak m/s | explained m/s | cuts | steps/frame | sim ms/frame | vs nod |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for solver in $solvers; do
  "$bin" "$root/presets/default.json" --headless --no-render --quiet --solver "$solver" \
    --frames 360 --metrics "$tmp/nod_$solver.json"
  for clip in nod "${clips[@]}"; do
    if [ "$clip" = nod ]; then
      json=$tmp/nod_$solver.json
    else
      json=$tmp/$(basename "$clip" .bvh)_$solver.json
      # The clip's length or 6 s, whichever is shorter.
      frames=$(python3 - "$clip" <<'PY'
import math, sys
words = open(sys.argv[1], errors="replace").read().split()
i = words.index("Frames:")
n, ft = int(words[i + 1]), float(words[i + 4])
print(min(360, max(1, math.ceil((n - 1) * ft * 60 - 1e-9))))
PY
)
      "$bin" "$root/presets/default.json" --headless --no-render --quiet --solver "$solver" \
        --set motion.clip="$(realpath "$clip")" --frames "$frames" --metrics "$json"
    fi
    python3 - "$json" "$tmp/nod_$solver.json" "$(basename "$clip")" "$solver" <<'PY'
import json, sys
m, nod = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
a = m["accuracy"]
cuts = m.get("motion", {}).get("cuts_carried", 0)
ms, nod_ms = m["ms"]["sim_steady"], nod["ms"]["sim_steady"]
print("| %s | %s | %d | %d | %.4f | %d | %d | %.2f | %.2f | %.2f | %.2f | %d | %d | %.1f | %.2fx |" % (
    sys.argv[3], sys.argv[4], m["frames"], a["nan_count"], a["max_strain"], a["head_penetrations"],
    a["torso_penetrations"],
    a["max_speed"], m["root_peak_speed"], m["rigid_peak_speed"], m["explained_peak_speed"], cuts,
    m["substeps"],
    ms, ms / nod_ms))
PY
  done
done
