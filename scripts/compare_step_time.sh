#!/usr/bin/env bash
# Step time of two builds of csmhair on one preset, both solvers, in one run: the two binaries
# alternate (A B A B ...) so that the machine's drift falls on both alike; prints each run's
# mean ms per frame (to completion, --metrics) and the ratio of the medians, B / A.
#   scripts/compare_step_time.sh BINARY_A BINARY_B [PRESET] [FRAMES] [REPEATS]
# SETS: settings for every run (e.g. SETS="hairstyle.strands=20000 hairstyle.guides=4000");
# SOLVERS: the solvers (default "cpu gpu").
set -euo pipefail
a=$1
b=$2
here=$(cd "$(dirname "$0")/.." && pwd)
preset=${3:-$here/presets/paper_fig1_straight.json}
frames=${4:-20}
repeats=${5:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sets=()
for set in ${SETS:-}; do sets+=(--set "$set"); done
for solver in ${SOLVERS:-cpu gpu}; do
  for r in $(seq "$repeats"); do
    for side in a b; do
      bin=$a
      [ "$side" = b ] && bin=$b
      "$bin" "$preset" --headless --no-render --quiet --frames "$frames" --solver "$solver" \
        ${sets[@]+"${sets[@]}"} --metrics "$tmp/$solver.$side.$r.json"
    done
  done
  python3 - "$tmp" "$solver" "$repeats" <<'PY'
import json, statistics, sys
tmp, solver, repeats = sys.argv[1], sys.argv[2], int(sys.argv[3])
ms = {s: [json.load(open(f"{tmp}/{solver}.{s}.{r}.json"))["ms"]["sim_mean"]
          for r in range(1, repeats + 1)] for s in "ab"}
fmt = lambda v: " ".join(f"{x:8.1f}" for x in v)
print(f"{solver}: A {fmt(ms['a'])} ms   B {fmt(ms['b'])} ms   "
      f"median B/A {statistics.median(ms['b']) / statistics.median(ms['a']):.3f}")
PY
done
