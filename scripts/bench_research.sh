#!/usr/bin/env bash
# Grooms of the research data sets (USC-HairSalon .data, CT2Hair .bin, strand PLY) and TressFX
# projects, each opened directly on the default scene (the mannequin nodding) with the head's
# field: FRAMES frames on each solver, the strands and points read and simulated, the fit's
# scale, what the import said, the worst strain and the particles inside the head. (Every
# writer's round trip is a test: tests/cpu/io_groom_formats_test.cpp.)
#   scripts/bench_research.sh BIN FRAMES FILE [FILE...]
# SOLVERS: a subset of "cpu gpu" (default both).
set -euo pipefail
bin=$1 frames=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| file | solver | strands | simulated points | max strain | in head | nan | what the import said |"
echo "|---|---|---|---|---|---|---|---|"
for file in "$@"; do
  for solver in ${SOLVERS:-cpu gpu}; do
    "$bin" "$file" --headless --frames "$frames" --no-render --solver "$solver" \
      --set collision.mode=head --set collision.head_shape=sdf --set head.motion=nod \
      --metrics "$tmp/m.json" >"$tmp/out.txt" 2>&1 || { echo "| $(basename "$file") | $solver | failed: $(tail -1 "$tmp/out.txt") |"; continue; }
    /usr/bin/python3 - "$tmp/m.json" "$(basename "$file")" "$solver" "$tmp/out.txt" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
a, g = m["accuracy"], m.get("groom", {})
said = [l.strip() for l in open(sys.argv[4]) if "groom file" in l]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {m.get('strands', '-')} | {m.get('particles', '-')} | "
      f"{100 * a['max_strain']:.2f} % | {a['head_penetrations']} | {a.get('nan_count', 0)} | "
      f"{(said[0] if said else '-')[:160]} |")
PY
  done
done
