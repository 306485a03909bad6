#!/usr/bin/env bash
# Strand contacts: cost and accuracy of each collision mode on a preset, per binary, the
# binaries alternated in one run (compare the rows of one run as ratios).
#   scripts/bench_contacts.sh PRESET FRAMES BIN...
# OLD_PRESETS=DIR OLD_BIN=BIN: that binary reads its presets from DIR and calls strand
# contacts "full". SOLVERS: a subset of "gpu cpu".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
preset=$1 frames=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "Load before: $(uptime | sed 's/.*load average: //')"
echo
echo "| binary | solver | mode | sim ms/frame | grid | contacts | pairs < 2r | < r (rest) | crossings/s | depth p50 / p99 / max (r) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for solver in ${SOLVERS:-gpu cpu}; do
  for mode in head strands; do
    for bin in "$@"; do
      dir=$root/presets
      m=$mode
      if [ "$bin" = "${OLD_BIN:-}" ]; then
        dir=${OLD_PRESETS:-$dir}
        [ "$mode" = head ] || m=full
      fi
      "$bin" "$dir/$preset.json" --headless --frames "$frames" --no-render --quiet \
        --solver "$solver" --set "collision.mode=$m" --metrics "$tmp/m.json" >/dev/null 2>&1
      /usr/bin/python3 - "$tmp/m.json" "$bin" "$solver" "$mode" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
a, ms = m["accuracy"], m["ms"]
st = ms["stages"]
def get(k, f="{:.0f}"):
    return f.format(a[k]) if k in a else "-"
rest = f" ({a['hair_penetrations_rest']})" if "hair_penetrations_rest" in a else ""
depth = (f"{a['hair_depth_p50']:.2f} / {a['hair_depth_p99']:.2f} / {a['hair_depth_max']:.2f}"
         if "hair_depth_p50" in a else "-")
print(f"| {sys.argv[2].split('/')[-1]} | {sys.argv[3]} | {sys.argv[4]} | {ms['sim_mean']:.1f} | "
      f"{st.get('grid', 0):.1f} | {st.get('contacts', 0):.1f} | {a['hair_contacts']} | "
      f"{a['hair_penetrations']}{rest} | {get('hair_crossings_per_s')} | {depth} |")
PY
    done
  done
done
