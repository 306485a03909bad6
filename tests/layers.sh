#!/usr/bin/env bash
# The modules point one way (docs/ARCHITECTURE.md section 2): gl -> sim -> render -> app, tools/
# beside app, and inside sim/ its layers, bottom to top: base, core, motion, param, head, groom, solver,
# gpu, run, verify. Fails on an include against that direction (a folder includes only folders
# below it or itself), on sim/verify in the app or the renderer, on sim/run in the renderer, on
# sim/gpu in the app (it has the solver factory), on GL outside sim/gpu, on the CPU library of
# sim/run reaching the GPU solver, on the panels including the viewer, on a GL_ constant outside
# gl/ (the simulation, the app, the renderer), on two modules (a header and its source) that
# include each other, on the app or the tools naming the Solver (they run scenes through
# Simulation and sim/verify's runners), on a second copy in a shader of a constant or a function
# both languages share, on a parameter block written out by hand beside the list both languages
# expand (a field added on one side only), and on a CPU test binary that links a GL, window or
# GUI library. tests/layers_scratch.sh makes a scratch edit of each kind and sees this fail.
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
layers=(base core motion param head groom solver gpu run verify)
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
# The app and the tools hold no solver: they run scenes through Simulation (the solver's state
# and diagnostics read through it) and sim/verify's SceneRunner, and make solvers by name
# (sim/run/make_solver.h).
check app '\bSolver\b' "app/ names no Solver"
check tools '\bSolver\b' "tools/ names no Solver"
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
# What the C++ and the shaders share is written once: the constants of
# shaders/sim/shared_constants.glsl (a distinctive one, of five digits or 10,000 or more, copied
# as a literal into another shader), pi (CSM_PI), the functions of shaders/sim/shared_functions.glsl and
# head_field_sample.glsl (defined again in another shader or C++ file), and the parameter blocks
# both languages expand from one list (a struct or block of that name with more in it than the
# list's expansion, or declared anywhere else).
if ! python3 - "$src" <<'PY'
import os, re, sys
src = sys.argv[1]
shaders = os.path.join(src, "shaders")
shared = {"sim/shared_constants.glsl", "sim/shared_functions.glsl", "sim/head_field_sample.glsl",
          "render/frame_uniforms.glsl"}
def files(top, ends):
    for root, _, names in os.walk(top):
        for n in names:
            if n.endswith(ends):
                yield os.path.join(root, n)
def code(text):
    return re.sub(r"//[^\n]*|/\*.*?\*/", "", text, flags=re.S)
glsl = {os.path.relpath(f, shaders): code(open(f).read())
        for f in files(shaders, (".glsl", ".comp", ".vert", ".frag"))}
cpp = {os.path.relpath(f, src): code(open(f).read())
       for top in ("app", "sim", "render", "gl", "tools")
       for f in files(os.path.join(src, top), (".h", ".cpp"))}
fail = []
# Constants: a literal of five significant digits or more, or of 10,000 or more, and pi.
defines = re.findall(r"#define (CSM_\w+) ([0-9][0-9.eE+-]*)u?\b", glsl["sim/shared_constants.glsl"])
def digits(v):
    return len(re.sub(r"[^0-9]", "", re.sub(r"[eE][+-]?[0-9]+$", "", v)).strip("0"))
distinct = [(n, v.rstrip(".0") if "." in v else v) for n, v in defines
            if digits(v) >= 5 or float(v) >= 10000]
for path, text in glsl.items():
    if path in shared or path.startswith("test/"):
        continue
    for name, value in distinct:
        if re.search(r"(?<![\w.])" + re.escape(value) + r"(\.0*)?u?(?![\w.])", text):
            fail.append(f"{path}: a copy of {name} ({value}); use {name}")
    if re.search(r"3\.14159", text):
        fail.append(f"{path}: a copy of pi; use CSM_PI")
# Functions: each shared one defined once.
names = set()
for f in ("sim/shared_functions.glsl", "sim/head_field_sample.glsl"):
    names.update(re.findall(r"^(?:CSM_SHARED\s+)?[\w]+\s+(\w+)\s*\(", glsl[f], re.M))
names.discard("if")
for path, text in list(glsl.items()) + list(cpp.items()):
    if path in shared:
        continue
    for name in names:
        if re.search(r"^\s*(?:inline\s+|static\s+)?[\w:<>]+\s+" + name + r"\s*\([^;]*\)\s*\{", text, re.M):
            fail.append(f"{path}: defines {name}() again (shaders/sim/shared_functions.glsl or head_field_sample.glsl has it)")
# Parameter blocks: nothing but the list's expansion.
lists = {"FrameUniforms": "CSM_FRAME_UNIFORMS", "SimParams": "CSM_SIM_PARAMS", "Substep": "CSM_SUBSTEP"}
for path, text in list(glsl.items()) + list(cpp.items()):
    for block, macro in lists.items():
        for m in re.finditer(r"\b(?:struct|uniform|buffer)\s+" + block + r"\s*\{([^}]*)\}", text):
            body = " ".join(m.group(1).split())
            if not re.fullmatch(macro + r"\(\w+\)", body):
                fail.append(f"{path}: {block} holds more than the list {macro} ({body[:80]})")
for f in fail:
    print("FAIL: " + f)
if not fail:
    print(f"ok: shared constants, functions and parameter blocks written once "
          f"({len(distinct)} constants, {len(names)} functions, {len(lists)} blocks)")
sys.exit(1 if fail else 0)
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
