#!/usr/bin/env bash
# The paper's Fig. 1 scene end to end on one solver (cpu: the CPU reference; gpu: the GPU
# solver, llvmpipe where there is no GPU): a quarter of its strands on the same scalp, 20
# frames. No NaN, strain within the limit, the metrics complete; on the GPU also per-stage
# times, hair-hair contact counts and the device.
#   tests/cli/headless.sh CSMHAIR SOURCE_DIR cpu|gpu
set -eu
bin=$1
src=$2
solver=$3
strands=2500
frames=20
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
preset=$src/presets/paper_fig1_straight.json
"$bin" "$preset" --headless --solver "$solver" --frames $frames --no-render \
  --set hairstyle.strands=$strands --metrics "$tmp/m.json"
python3 - "$tmp/m.json" "$preset" "$solver" $strands $frames <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
p = json.load(open(sys.argv[2]))
solver, strands, frames = sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
limit = p["sim"]["strain_limit"]
a = m["accuracy"]
print("solver", m["solver"], "device", m.get("device"), "strands", m["strands"],
      "particles", m["particles"], "ms/frame", m["ms"]["sim_mean"], "stages", m["ms"].get("stages"))
print("max_strain", a["max_strain"], "nan", a["nan_count"], "contacts", a.get("hair_contacts"),
      "penetrations", a.get("hair_penetrations"))
assert m["solver"] == solver, m["solver"]
particles = strands * p["hairstyle"]["particles_per_strand"]
assert m["strands"] == strands and m["particles"] == particles, m
assert m["frames"] == frames
for key in ["frame_dt", "substeps", "solver"]: assert key in m, key
for key in ["sim_mean", "sim_p95"]: assert m["ms"][key] > 0, key
for key in ["max_strain", "mean_strain", "head_penetrations", "max_speed", "nan_count"]:
    assert key in a, key
assert a["nan_count"] == 0
assert a["max_speed"] > 0
# What the scene took: the process's peak, and the GPU solver's buffers by kind, at least the
# strands' positions, velocities, predictions and rest (4 vec4 a particle), contacts among them.
mem = m["memory"]
assert mem["peak_rss_bytes"] > 0, mem
if solver == "gpu":
    kinds = mem["solver_buffers_bytes"]
    assert kinds["strands"] >= 64 * particles and kinds["contacts"] > 0, kinds
    assert mem["solver_buffers_total_bytes"] == sum(kinds.values()), mem
    assert abs(mem["solver_bytes_per_particle"] * particles - mem["solver_buffers_total_bytes"]) < 1, mem
if solver == "cpu":
    # Float read-back of double positions: allow rounding of the last bits.
    assert a["max_strain"] <= limit + 1e-5, (a["max_strain"], limit)
    sys.exit(0)
# GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)": a name, not the placeholder.
assert isinstance(m["device"], str) and m["device"] not in ("", "gpu", "cpu"), m["device"]
stages = m["ms"]["stages"]
for key in ["integrate", "shape_matching", "strain_limiting", "grid", "contacts"]:
    assert key in stages and stages[key] > 0, (key, stages)
# The stages are parts of the frame: together no longer than it (10% for timer rounding).
assert sum(stages.values()) <= 1.1 * m["ms"]["sim_mean"], (stages, m["ms"]["sim_mean"])
# The GPU limits strain in float: positions near 0.3 m round by 3e-8 m, a few 1e-6 of a
# 1.8 cm segment; 1e-4 leaves room for other drivers.
assert a["max_strain"] <= limit + 1e-4, (a["max_strain"], limit)
# Fig. 1's scalp is dense even at a quarter of its strands: contacts (pairs closer than 2r)
# everywhere, real crossings (closer than r) fewer.
assert a["hair_contacts"] > 1000, a["hair_contacts"]
assert 0 < a["hair_penetrations"] < a["hair_contacts"], a
# Every frame's candidates fit the buffers (reserved from the rest groom), and no segment is
# too long for the grid: the metrics say so either way.
assert a["hair_list_overflows"] == 0, a
assert a["hair_oversize_segments_max"] == 0, a
assert a["hair_crowded_segments_max"] == 0, a
PY
