#!/usr/bin/env bash
# Hair-hair cost and accuracy by collision mode and strand count (issue "hair-hair that holds
# strands apart"): every mode of collision.mode at each strand count, on one preset, one run;
# writes OUT/modes.csv for scripts/charts.py (chart "modes") and prints it as a table.
#   scripts/bench_modes.sh OUT [PRESET] [FRAMES] [STRANDS...]
# Defaults: paper_fig1_straight, 4 frames, 1000 3000 10000 30000 100000 strands.
# MODES (default "off head strands") and SOLVERS (default "gpu") pick a subset; a mode
# written MODE:N runs with N contact iterations a substep (collision.iterations), as its own
# row and line ("strands:4"); MODE@MODEL picks collision.contact_model ("strands@penalty": the
# paper's penalty forces).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$1
preset=${2:-paper_fig1_straight}
frames=${3:-4}
shift $(($# < 3 ? $# : 3))
counts=${*:-1000 3000 10000 30000 100000}
bin=${CSMHAIR:-$root/build/app/csmhair}
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
csv=$out/modes.csv
columns=$root/scripts/contact_columns.py
echo "solver,mode,$(/usr/bin/python3 "$columns" --header strands particles frames)" >"$csv"
echo "Load before: $(uptime | sed 's/.*load average: //'); $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
for solver in ${SOLVERS:-gpu}; do
  for n in $counts; do
    for mode in ${MODES:-off head strands}; do
      base=${mode%%:*}
      sets=(--set "collision.mode=${base%%@*}" --set "hairstyle.strands=$n")
      [[ $mode == *:* ]] && sets+=(--set "collision.iterations=${mode#*:}")
      [[ $base == *@* ]] && sets+=(--set "collision.contact_model=${base#*@}")
      if ! "$bin" "$root/presets/$preset.json" --headless --frames "$frames" --no-render --quiet \
        --solver "$solver" "${sets[@]}" --metrics "$tmp/m.json" >"$tmp/log" 2>&1; then
        echo "bench_modes.sh: $solver $mode $n strands failed:" >&2
        cat "$tmp/log" >&2
        exit 1
      fi
      echo "$solver,$mode,$(/usr/bin/python3 "$columns" "$tmp/m.json" strands particles frames)" \
        >>"$csv"
      tail -n 1 "$csv"
    done
  done
done
