#!/usr/bin/env bash
# The modules point one way (docs/DESIGN.md section 2): gl -> sim -> render -> app, tools/
# beside app. Fails on an include against that direction, on sim/ code calling GL outside
# sim/gpu, and on a CPU test binary that links a GL, window or GUI library.
#   tests/layers.sh SOURCE_DIR CPU_TEST_BINARY
set -u
src=$1
cpu_tests=$2
fail=0
check() {  # check DIR PATTERN WHY
  local hits
  hits=$(grep -rnE "$2" "$src/$1" --include='*.h' --include='*.cpp' 2>/dev/null)
  if [ -n "$hits" ]; then
    echo "FAIL: $3:"; echo "$hits"; fail=1
  else
    echo "ok: $3"
  fi
}
check gl '#include "(sim|render|app|tools)/' "gl/ includes nothing above it"
check sim '#include "(render|app|tools)/' "sim/ includes neither render/, app/ nor tools/"
check render '#include "(app|tools)/' "render/ includes neither app/ nor tools/"
# Only the GPU solver talks to GL, and only through gl/.
hits=$(grep -rnE '#include [<"](epoxy|GL|EGL)/|#include "gl/' "$src/sim" --include='*.h' --include='*.cpp' | grep -v "^$src/sim/gpu/")
if [ -n "$hits" ]; then echo "FAIL: GL outside sim/gpu:"; echo "$hits"; fail=1; else echo "ok: GL in sim/ only under sim/gpu"; fi
# GL calls behind gl/: no raw gl* entry point (glFoo( or epoxy's) in sim/, render/, app/ or
# tools/; they call gl/'s wrappers.
hits=$(grep -rnE '\bgl[A-Z][A-Za-z0-9]*\(' "$src/sim" "$src/render" "$src/app" "$src/tools" --include='*.h' --include='*.cpp')
if [ -n "$hits" ]; then echo "FAIL: raw GL calls outside gl/:"; echo "$hits"; fail=1; else echo "ok: GL calls only in gl/"; fi
libs=$(ldd "$cpu_tests" | grep -iE 'libepoxy|libEGL|libGL|libOpenGL|libglfw|libimgui|libX11')
if [ -n "$libs" ]; then
  echo "FAIL: the CPU tests link GL, window or GUI libraries:"; echo "$libs"; fail=1
else
  echo "ok: the CPU tests link no GL, window or GUI library"
fi
exit $fail
