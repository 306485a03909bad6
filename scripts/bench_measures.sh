#!/usr/bin/env bash
# What the measures (--metrics) cost against the run they measure: the default preset at
# STRANDS strands (default 30,000), every strand simulated (hairstyle.guides=0), FRAMES frames
# (default 2) on the GPU solver without drawing, each binary with and without --metrics: wall
# time and peak RSS (/usr/bin/time), and the hair-hair measures the metrics give.
#   scripts/bench_measures.sh BIN [BIN...]      (e.g. an older build's csmhair, then build/app/csmhair)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
strands=${STRANDS:-30000}
frames=${FRAMES:-2}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "Load before: $(uptime | sed 's/.*load average: //')"
echo
echo "| binary | --metrics | wall s | peak RSS MB | ratio: wall | ratio: RSS | stride | hair contacts | pairs < r | crossings | depth p99 (r) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
k=0
for bin in "$@"; do
  k=$((k + 1))
  for m in no yes; do
    extra=()
    [ "$m" = yes ] && extra=(--metrics "$tmp/m$k.json")
    /usr/bin/time -f "%e %M" -o "$tmp/t$k$m" "$bin" "$root/presets/default.json" --headless \
      --no-render --quiet --frames "$frames" --set hairstyle.strands="$strands" \
      --set hairstyle.guides=0 "${extra[@]}" 2>"$tmp/e$k$m" || { cat "$tmp/e$k$m" >&2; exit 1; }
  done
  /usr/bin/python3 - "$tmp" "$k" "$bin" <<'PY'
import json, sys
tmp, k, name = sys.argv[1], sys.argv[2], sys.argv[3]
t = {m: [float(v) for v in open(f"{tmp}/t{k}{m}").read().split()[-2:]] for m in ("no", "yes")}
a = json.load(open(f"{tmp}/m{k}.json"))["accuracy"]
for m in ("no", "yes"):
    wall, rss = t[m][0], t[m][1] / 1024
    ratio = f"{wall / t['no'][0]:.2f}x | {rss / (t['no'][1] / 1024):.2f}x"
    meas = (f"{a.get('hair_measure_stride', 1)} | {a['hair_contacts']:,} | {a['hair_penetrations']:,} | "
            f"{a['hair_crossings']:,} | {a['hair_depth_p99']:.2f}") if m == "yes" else "| | | |"
    print(f"| {name} | {m} | {wall:.2f} | {rss:.0f} | {ratio} | {meas} |")
PY
done
echo
echo "Load after: $(uptime | sed 's/.*load average: //')"
