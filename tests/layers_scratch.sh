#!/usr/bin/env bash
# tests/layers.sh can fail: each rule of the house it keeps, broken by a scratch edit in a copy of
# the tree, makes it fail naming that rule; the copy unedited passes.
#   tests/layers_scratch.sh SOURCE_DIR CPU_TEST_BINARY
set -u
src=$1
cpu_tests=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
mkdir -p "$work/tree"
cp -r "$src"/{app,sim,render,gl,tools,shaders} "$work/tree/"
# expect_fail WHAT PATTERN FILE EDIT: EDIT (a python expression over the file's text `t`) made to
# FILE, layers.sh must fail with a line matching PATTERN.
expect_fail() {
  local what=$1 pattern=$2 file=$3 edit=$4
  cp "$work/tree/$file" "$work/original"
  python3 -c "import sys; p=sys.argv[1]; t=open(p).read(); t=$edit; open(p,'w').write(t)" \
    "$work/tree/$file"
  local out status
  out=$(bash "$src/tests/layers.sh" "$work/tree" "$cpu_tests" 2>&1)
  status=$?
  cp "$work/original" "$work/tree/$file"
  if [ "$status" -eq 0 ]; then
    echo "FAIL: $what: layers.sh passed"; fail=1
  elif ! grep -qE "FAIL: .*$pattern" <<<"$out"; then
    echo "FAIL: $what: layers.sh failed, but not on '$pattern':"; grep FAIL <<<"$out"; fail=1
  else
    echo "ok: $what: $(grep -m1 -E "FAIL: .*$pattern" <<<"$out")"
  fi
}

if out=$(bash "$src/tests/layers.sh" "$work/tree" "$cpu_tests" 2>&1); then
  echo "ok: the tree as it is passes"
else
  echo "FAIL: the unedited copy fails:"; grep FAIL <<<"$out"; fail=1
fi
expect_fail "app/ naming Solver" "app/ names no Solver" app/headless.cpp \
  "t.replace('namespace csm {', 'namespace csm {\nvoid run(Solver& solver);', 1)"
expect_fail "tools/ naming Solver" "tools/ names no Solver" tools/bench/bench.cpp \
  "t.replace('namespace csm::bench {', 'namespace csm::bench {\nstd::unique_ptr<Solver> made;', 1)"
expect_fail "pi again in a shader" "a copy of pi" shaders/render/head.frag \
  "'const float kPi = 3.14159265358979;\n' + t"
expect_fail "a shared constant again in a shader" "a copy of CSM_VOLUME_UNIT" \
  shaders/sim/volume_splat.comp "t + '\nconst float kUnit = 16777216.0;\n'"
expect_fail "the head field's sample again in a shader" "defines headFieldAt" \
  shaders/render/hair_followers.comp \
  "t + '\nvec4 headFieldAt(ivec3 d, vec3 o, float c, vec3 p) { return vec4(0.0); }\n'"
expect_fail "the wind field again in C++" "defines windField" sim/solver/wind.cpp \
  "t.replace('namespace csm {', 'namespace csm {\nglm::dvec3 windField(double t) {\n  return glm::dvec3(t);\n}', 1)"
expect_fail "a uniform field added in C++ only" "FrameUniforms holds more than the list" \
  render/frame_uniforms.h \
  "t.replace('CSM_FRAME_UNIFORMS(CSM_CPP_FIELD)', 'CSM_FRAME_UNIFORMS(CSM_CPP_FIELD)\n  glm::vec4 extra;')"
expect_fail "a uniform field added in GLSL only" "FrameUniforms holds more than the list" \
  shaders/render/frame.glsl \
  "t.replace('CSM_FRAME_UNIFORMS(CSM_GLSL_FIELD)', 'CSM_FRAME_UNIFORMS(CSM_GLSL_FIELD)\n  vec4 uExtra;')"
expect_fail "a solver parameter added in GLSL only" "SimParams holds more than the list" \
  shaders/sim/common.glsl \
  "t.replace('CSM_SIM_PARAMS(CSM_MEMBER)', 'CSM_SIM_PARAMS(CSM_MEMBER)\n  float extra;', 1)"
exit $fail
