#!/usr/bin/env bash
# Each kind of bad input gets its message (naming the file and JSON path) and exit status 2.
set -u
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib/expect.sh"

printf '{"sim": {"dt": "fast"}}' >"$tmp/type.json"
printf '{"sim": {"substeps": 0}}' >"$tmp/range.json"
printf '{"wind": {"strenght": 3}}' >"$tmp/unknown.json"
printf '{\n  "sim": {\n    "dt": 0.01,\n  }\n' >"$tmp/broken.json"
printf '{"hairstyle": {"strands": 1000000, "particles_per_strand": 64}}' >"$tmp/huge.json"

expect 2 "type.json: sim.dt: expected a number, got a string" -- "$tmp/type.json" --headless --frames 1 --solver cpu
expect 2 "range.json: sim.substeps: value 0 is out of range [1, 64]" -- "$tmp/range.json" --headless --frames 1 --solver cpu
expect 2 'unknown.json: wind.strenght: unknown key (did you mean "strength"?)' -- "$tmp/unknown.json" --headless --solver cpu
expect 2 "broken.json:4:3 (byte" -- "$tmp/broken.json" --headless --solver cpu
expect 2 "invalid JSON" -- --validate "$tmp/broken.json"
expect 2 "hairstyle.strands" -- "$tmp/huge.json" --headless --solver cpu
expect 2 "cannot open" -- "$tmp/missing.json" --headless --solver cpu
expect 2 "--set sim.substeps=abc: expected an integer" -- --headless --solver cpu --set sim.substeps=abc
expect 2 "--set sim.nothing=1: unknown parameter" -- --headless --solver cpu --set sim.nothing=1
expect 2 'sim.stiffness_model=stiff: "stiff" is not one of paper|calibrated' -- --headless --solver cpu --set sim.stiffness_model=stiff
expect 2 "sim.window_length=2: value 2 is out of range [0.002, 0.1]" -- --headless --solver cpu --set sim.window_length=2
expect 0 "sim.bending_stiffness" -- --list-params
# A stiffness that asks for more steps than allowed runs, and says so even with --quiet.
expect 0 "warning: the stiffness asks for" -- --headless --no-render --quiet --solver cpu --frames 1 --set hairstyle.strands=50 --set sim.window_length=0.01 --set sim.max_substeps=4
# Soft hair without the DFTL it needs runs, and says how much (sim/solver/stiffness.h, softHairDftl).
expect 0 "gains energy unless sim.dftl is at least 0.9" -- --headless --no-render --quiet --solver cpu --frames 1 --set hairstyle.strands=50 --set sim.bending_stiffness=1e-4 --set sim.substeps=16
expect 2 "unknown option --frobnicate" -- --frobnicate
expect 2 "--frames -3: needs N (a whole number >= 0) or A-B" -- --frames -3
# An export name that no writer takes is refused before anything runs.
expect 2 "--export-hair out.tfx: the name must end in .hair (cyHair), .obj (OBJ curves), .data" -- --headless --solver cpu --export-hair out.tfx
expect 0 "ok" -- --validate "$src"/presets/*.json
exit $fail
