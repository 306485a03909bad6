#!/usr/bin/env bash
# The modules point one way (docs/ARCHITECTURE.md section 2): gl -> sim -> render -> app, tools/
# beside app, and inside sim/ its layers, bottom to top: base, core, param, head, groom, solver,
# gpu, run, verify. Fails on an include against that direction (a folder includes only folders
# below it or itself), on sim/verify in the app or the renderer, on sim/run in the renderer, on
# sim/gpu in the app (it has the solver factory), on GL outside sim/gpu, on the CPU library of
# sim/run reaching the GPU solver, on the panels including the viewer, on a GL_ constant outside
# gl/ (the simulation, the app, the renderer), on two modules (a header and its source) that
# include each other, and on a CPU test binary that links a GL, window or GUI library.
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
# Inside sim/: each layer includes only the layers below it and itself.
layers=(base core param head groom solver gpu run verify)
for i in "${!layers[@]}"; do
  above=("${layers[@]:i+1}")
  [ ${#above[@]} -eq 0 ] && continue
  pattern="#include \"sim/($(IFS='|'; echo "${above[*]}"))/"
  check "sim/${layers[i]}" "$pattern" "sim/${layers[i]} includes no layer above it (${above[*]})"
done
hits=$(find "$src/sim" -maxdepth 1 -name '*.h' -o -maxdepth 1 -name '*.cpp')
if [ -n "$hits" ]; then echo "FAIL: sim/ sources outside its layers:"; echo "$hits"; fail=1; else echo "ok: every sim/ source in a layer"; fi
# The verification layer is for tests and tools: the program does not include it.
check app '#include "sim/verify/' "app/ does not include sim/verify"
check render '#include "sim/verify/' "render/ does not include sim/verify"
# The renderer draws a FrameView (render/renderer.h), which the app builds from the Simulation:
# it knows frames, not simulations.
check render '#include "sim/run/' "render/ includes nothing of sim/run"
# The app makes its solvers, and reads the GPU one's pass profile, through the solver factory:
# nothing of sim/gpu's own headers.
check app '#include "sim/gpu/' "app/ reaches sim/gpu only through sim/run/make_solver.h"
# sim/run's CPU library needs no GL: only the solver factory (its own library) knows the GPU one.
hits=$(grep -rnE '#include "sim/gpu/' "$src/sim/run" --include='*.h' --include='*.cpp' | grep -v "^$src/sim/run/make_solver\.")
if [ -n "$hits" ]; then echo "FAIL: sim/run reaches sim/gpu outside make_solver:"; echo "$hits"; fail=1; else echo "ok: sim/run reaches sim/gpu only in make_solver"; fi
# Only the GPU solver talks to GL, and only through gl/.
hits=$(grep -rnE '#include [<"](epoxy|GL|EGL)/|#include "gl/' "$src/sim" --include='*.h' --include='*.cpp' | grep -v "^$src/sim/gpu/")
if [ -n "$hits" ]; then echo "FAIL: GL outside sim/gpu:"; echo "$hits"; fail=1; else echo "ok: GL in sim/ only under sim/gpu"; fi
# GL calls behind gl/: no raw gl* entry point (glFoo( or epoxy's) in sim/, render/, app/ or
# tools/; they call gl/'s wrappers.
hits=$(grep -rnE '\bgl[A-Z][A-Za-z0-9]*\(' "$src/sim" "$src/render" "$src/app" "$src/tools" --include='*.h' --include='*.cpp')
if [ -n "$hits" ]; then echo "FAIL: raw GL calls outside gl/:"; echo "$hits"; fail=1; else echo "ok: GL calls only in gl/"; fi
# The panels see the viewer through PanelView and PanelRequests (app/panels.h), not its class.
hits=$(grep -nE '#include "app/viewer\.h"' "$src"/app/panels*.h "$src"/app/panels*.cpp 2>/dev/null)
if [ -n "$hits" ]; then echo "FAIL: the panels include the viewer:"; echo "$hits"; fail=1; else echo "ok: the panels do not include app/viewer.h"; fi
# GL's constants stay behind gl/ too: the simulation, the renderer and the app name formats,
# attachments, usage, image access, primitives, ... with gl/'s typed enums (gl/enums.h).
check sim '\bGL_[A-Z0-9_]+' "sim/ names no GL_ constant (gl/enums.h has typed ones)"
check app '\bGL_[A-Z0-9_]+' "app/ names no GL_ constant (gl/enums.h has typed ones)"
check render '\bGL_[A-Z0-9_]+' "render/ names no GL_ constant (gl/enums.h has typed ones)"
# No two modules (a header and its source, app/viewer.{h,cpp}) include each other: a pair that
# does is one piece split in two, or a dependency that should point one way.
if ! python3 - "$src" <<'PY'
import os, re, sys
src = sys.argv[1]
include = re.compile(r'^\s*#include\s+"([^"]+)"', re.M)
uses = {}
for top in ("gl", "sim", "render", "app", "tools"):
    for root, _, files in os.walk(os.path.join(src, top)):
        for f in files:
            if f.endswith((".h", ".cpp")):
                rel = os.path.relpath(os.path.join(root, f), src)
                module = os.path.splitext(rel)[0]
                text = open(os.path.join(src, rel), errors="replace").read()
                uses.setdefault(module, set()).update(
                    m for m in (os.path.splitext(h)[0] for h in include.findall(text)) if m != module)
pairs = sorted({tuple(sorted((a, b))) for a, used in uses.items() for b in used
                if b in uses and a in uses[b]})
for a, b in pairs:
    print(f"FAIL: {a} and {b} include each other")
if not pairs:
    print(f"ok: no two modules include each other ({len(uses)} modules)")
sys.exit(1 if pairs else 0)
PY
then
  fail=1
fi
libs=$(ldd "$cpu_tests" | grep -iE 'libepoxy|libEGL|libGL|libOpenGL|libglfw|libimgui|libX11')
if [ -n "$libs" ]; then
  echo "FAIL: the CPU tests link GL, window or GUI libraries:"; echo "$libs"; fail=1
else
  echo "ok: the CPU tests link no GL, window or GUI library"
fi
exit $fail
