#!/usr/bin/env bash
# A groom with the flaws of real ones (scripts/make_flawed_groom.py: TressFX 4.x, 2,228 strands x
# 32 points, a 7.5 um strand, 31 segments under a micrometre) opened directly, builds against
# each other in one run: ms a frame, the steps the stiffness asks for, the strain and the
# particles in the head after FRAMES frames. Builds and solvers alternate ROUNDS times.
#   scripts/bench_import.sh FRAMES ROUNDS BIN [BIN...]
# SOLVERS: a subset of "gpu cpu" (default both).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
frames=$1 rounds=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 "$root/scripts/make_flawed_groom.py" "$tmp/flawed.tfx" >/dev/null
echo "Load before: $(uptime | sed 's/.*load average: //')"
echo
echo "| round | build | solver | ms/frame | steps a frame | strands at alpha = 1 | max strain | particles in the head | strands dropped |"
echo "|---|---|---|---|---|---|---|---|---|"
for round in $(seq "$rounds"); do
  for solver in ${SOLVERS:-gpu cpu}; do
    for bin in "$@"; do
      "$bin" "$tmp/flawed.tfx" --headless --frames "$frames" --no-render --quiet \
        --solver "$solver" --metrics "$tmp/m.json" >/dev/null 2>&1 || true
      build=$(git -C "$(dirname "$bin")/../.." rev-parse --short HEAD 2>/dev/null || echo "$bin")
      /usr/bin/python3 - "$tmp/m.json" "$round" "$build" "$solver" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
a, st, g = m["accuracy"], m["stiffness"], m["groom"]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {m['ms']['sim_mean']:.1f} | "
      f"{m['substeps']} (asked {st['substeps_wanted']}) | {st.get('strands_at_alpha_1', '-')} | "
      f"{100 * a['max_strain']:.2f} % | {a['head_penetrations']} | {g.get('dropped_strands', '-')} |")
PY
      rm -f "$tmp/m.json"
    done
  done
done
echo
echo "Load after: $(uptime | sed 's/.*load average: //')"
