#!/usr/bin/env bash
# Hair-hair cost and accuracy by collision mode and strand count (issue "hair-hair that holds
# strands apart"): every mode of collision.mode at each strand count, on one preset, one run;
# writes OUT/modes.csv for scripts/charts.py (chart "modes") and prints it as a table.
#   scripts/bench_modes.sh OUT [PRESET] [FRAMES] [STRANDS...]
# Defaults: paper_fig1_straight, 4 frames, 1000 3000 10000 30000 100000 strands.
# MODES (default "off head strands") and SOLVERS (default "gpu") pick a subset; a mode
# written MODE:N runs with N contact iterations a substep (collision.iterations), as its own
# row and line ("strands:4").
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
echo "solver,mode,strands,particles,frames,sim_ms,grid_ms,contacts_ms,pairs_2r,pairs_r,pairs_r_rest,crossings_per_s,crossings_close_per_s,depth_p50,depth_p99,depth_max" >"$csv"
echo "Load before: $(uptime | sed 's/.*load average: //'); $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
for solver in ${SOLVERS:-gpu}; do
  for n in $counts; do
    for mode in ${MODES:-off head strands}; do
      sets=(--set "collision.mode=${mode%%:*}" --set "hairstyle.strands=$n")
      [[ $mode == *:* ]] && sets+=(--set "collision.iterations=${mode#*:}")
      if ! "$bin" "$root/presets/$preset.json" --headless --frames "$frames" --no-render --quiet \
        --solver "$solver" "${sets[@]}" --metrics "$tmp/m.json" >"$tmp/log" 2>&1; then
        echo "bench_modes.sh: $solver $mode $n strands failed:" >&2
        cat "$tmp/log" >&2
        exit 1
      fi
      /usr/bin/python3 - "$tmp/m.json" "$solver" "$mode" "$n" "$frames" >>"$csv" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
a, ms = m["accuracy"], m["ms"]
st = ms["stages"]
def get(k):
    return f"{a[k]}" if k in a else ""
# Crossings are counted against the last list: none when the lists did not fit (not measured).
def crossings(k):
    return "" if a.get("hair_list_overflows", 0) > 0 else get(k)
print(",".join([sys.argv[2], sys.argv[3], sys.argv[4], str(m["particles"]),
                sys.argv[5], f"{ms['sim_mean']:.2f}", f"{st.get('grid', 0):.2f}",
                f"{st.get('contacts', 0):.2f}", get("hair_contacts"), get("hair_penetrations"),
                get("hair_penetrations_rest"), crossings("hair_crossings_per_s"),
                crossings("hair_crossings_close_at_rest_per_s"),
                get("hair_depth_p50"), get("hair_depth_p99"), get("hair_depth_max")]))
PY
      tail -n 1 "$csv"
    done
  done
done
