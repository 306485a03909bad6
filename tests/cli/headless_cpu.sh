#!/usr/bin/env bash
# The paper's Fig. 1 scene, 60 frames on the CPU reference: no NaN, strain within the limit.
set -eu
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" "$src/presets/paper_fig1_straight.json" --headless --solver cpu --frames 60 \
  --no-render --metrics "$tmp/m.json"
python3 - "$tmp/m.json" "$src/presets/paper_fig1_straight.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
p = json.load(open(sys.argv[2]))
limit = p["sim"]["strain_limit"]
print("strands", m["strands"], "particles", m["particles"], "ms/frame", m["ms"]["sim_mean"],
      "max_strain", m["accuracy"]["max_strain"], "nan", m["accuracy"]["nan_count"])
assert m["strands"] == 10000 and m["particles"] == 160000, m
assert m["frames"] == 60
for key in ["frame_dt", "substeps", "solver"]: assert key in m, key
for key in ["sim_mean", "sim_p95"]: assert m["ms"][key] > 0, key
a = m["accuracy"]
for key in ["max_strain", "mean_strain", "head_penetrations", "max_speed", "nan_count"]: assert key in a, key
assert a["nan_count"] == 0
# Float read-back of double positions: allow rounding of the last bits.
assert a["max_strain"] <= limit + 1e-5, (a["max_strain"], limit)
assert a["max_speed"] > 0
PY
