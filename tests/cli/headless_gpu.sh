#!/usr/bin/env bash
# The paper's Fig. 1 scene, 60 frames on the GPU solver (llvmpipe where there is no GPU):
# no NaN, strain within the limit, per-stage GPU times, hair-hair contact counts and the
# device in the metrics.
set -eu
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" "$src/presets/paper_fig1_straight.json" --headless --solver gpu --frames 60 \
  --no-render --metrics "$tmp/m.json"
python3 - "$tmp/m.json" "$src/presets/paper_fig1_straight.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
p = json.load(open(sys.argv[2]))
limit = p["sim"]["strain_limit"]
a = m["accuracy"]
print("device", m["device"], "strands", m["strands"], "particles", m["particles"],
      "ms/frame", m["ms"]["sim_mean"], "stages", m["ms"]["stages"])
print("max_strain", a["max_strain"], "nan", a["nan_count"], "contacts", a["hair_contacts"],
      "penetrations", a["hair_penetrations"])
assert m["strands"] == 10000 and m["particles"] == 160000, m
assert m["frames"] == 60
assert m["solver"] == "gpu"
# GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)": a name, not the placeholder.
assert isinstance(m["device"], str) and m["device"] not in ("", "gpu", "cpu"), m["device"]
for key in ["sim_mean", "sim_p95"]: assert m["ms"][key] > 0, key
stages = m["ms"]["stages"]
for key in ["integrate", "shape_matching", "strain_limiting", "grid", "contacts"]:
    assert key in stages and stages[key] > 0, (key, stages)
# The stages are parts of the frame: together no longer than it (10% for timer rounding).
assert sum(stages.values()) <= 1.1 * m["ms"]["sim_mean"], (stages, m["ms"]["sim_mean"])
assert a["nan_count"] == 0
# The GPU limits strain in float: positions near 0.3 m round by 3e-8 m, a few 1e-6 of a
# 1.8 cm segment; 1e-4 leaves room for other drivers.
assert a["max_strain"] <= limit + 1e-4, (a["max_strain"], limit)
assert a["max_speed"] > 0
# Fig. 1 packs 10,000 strands on the scalp: contacts (pairs closer than 2r) are everywhere,
# real crossings (closer than r) fewer.
assert a["hair_contacts"] > 1000, a["hair_contacts"]
assert 0 < a["hair_penetrations"] < a["hair_contacts"], a
# Every frame's candidates fit the buffers (reserved from the rest groom), and no segment is
# too long for the grid: the metrics say so either way.
assert a["hair_list_overflows"] == 0, a
assert a["hair_oversize_segments_max"] == 0, a
assert a["hair_crowded_segments_max"] == 0, a
PY
