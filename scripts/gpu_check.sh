#!/usr/bin/env bash
# The one command for a machine with a GPU (docs/BENCHMARKS.md, "On a GPU"): names the OpenGL
# device and its driver, runs the GPU test tier on it, and prints the benchmark table as
# Markdown, ready for BENCHMARKS: the default preset, Fig. 1 and Fig. 3, every collision mode,
# the solver alone and with drawing at 1920x1080, ms a frame and frames a second. On a software
# renderer (llvmpipe) it runs too, with fewer frames, and says so at the top of the table.
#   scripts/gpu_check.sh [BUILD_DIR] [--require-gpu]      (BUILD_DIR default: build)
# --require-gpu: a software renderer is an error (exit 1 before any row), not a smaller run.
# BUILD_DIR holds app/csmhair and tests/csm_tests_gpu (a build tree, or those two copied with
# its CMakeCache.txt). Environment: FRAMES (a row's frames: 120 on a GPU, 3 in software),
# TESTS=0 (no test tier), BENCH=0 (no table), KERNELS (the GPU solver's paths to time, each
# a row: "auto" the one the device gets, or strand and/or particle; default "strand particle"),
# SCENES (default, fig1, fig3; groom too on request: the default hairstyle grown to GROOM_STRANDS
# strands, default 100,000, at 32 points, written as cyHair, opened with the default guides and
# render.children=0, its rows' strands "simulated of drawn"), MODES (collision modes; default all five), DRAW (no, yes), JOBS (test processes at once; default the cores), LOG_DIR (where the
# tests' and runs' logs go; default a temporary folder), CSM_EGL_DEVICE (the device; see --help).
# Exit status: 0 when the tests passed and every row ran, else 1.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
require_gpu=0
[ "${2:-}" = --require-gpu ] && require_gpu=1
build=$(cd "${1:-$root/build}" && pwd) || exit 1
bin=$build/app/csmhair
tests=$build/tests/csm_tests_gpu
logs=${LOG_DIR:-$(mktemp -d)}
mkdir -p "$logs"
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
status=0
[ -x "$bin" ] || { echo "gpu_check: no $bin (build first: scripts/setup.sh)" >&2; exit 1; }

# The tests find presets and data under the source folder their build was configured from; a
# build carried to another machine gets a link from there to this checkout.
if [ -f "$build/CMakeCache.txt" ]; then
  baked=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
  if [ -n "$baked" ] && [ ! -e "$baked" ]; then
    mkdir -p "$(dirname "$baked")" && ln -s "$root" "$baked" &&
      echo "gpu_check: linked $baked -> $root (the build's source folder)"
  fi
fi

echo "## Device"
echo
echo '```'
echo "date:       $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "commit:     $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?')"
echo "cpu:        $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //') ($(nproc) cores)"
if command -v nvidia-smi >/dev/null 2>&1; then
  echo "nvidia-smi: $(nvidia-smi --query-gpu=index,name,driver_version,memory.total \
    --format=csv,noheader 2>&1 | tr '\n' ';')"
fi
info=$("$bin" --info 2>&1)
info_status=$?
echo "$info"
echo '```'
if [ $info_status -ne 0 ]; then
  echo "gpu_check: no OpenGL context; nothing to measure" >&2
  exit 1
fi
software=0
grep -q "(software)" <<<"$info" && software=1
device=$(sed -n 's/^GL renderer: *//p' <<<"$info" | sed 's/ (software)$//')
driver=$(sed -n 's/^GL version: *//p' <<<"$info")
frames=${FRAMES:-120}
if [ $software -eq 1 ] && [ $require_gpu -eq 1 ]; then
  echo "gpu_check: --require-gpu: OpenGL runs on a software renderer ($device)" >&2
  exit 1
fi
if [ $software -eq 1 ]; then
  frames=${FRAMES:-3}
  echo
  echo "**Software renderer ($device): these are CPU figures, not a GPU's.**"
fi

if [ "${TESTS:-1}" != 0 ] && [ -x "$tests" ]; then
  echo
  echo "## GPU test tier"
  echo
  # One process per test file (as ctest runs them, each its own context), $jobs at once.
  tags=$("$tests" -# --list-tags 2>/dev/null | grep -o '\[#[^]]*\]')
  t0=$(date +%s)
  # shellcheck disable=SC2016
  xargs -P "$jobs" -I{} sh -c '
    t=$1; name=${t#[#}; name=${name%]}; s=$(date +%s)
    if "$2" -# "$t" >"$3/test_$name.log" 2>&1; then r=passed; else r=FAILED; fi
    echo "| $name | $r | $(( $(date +%s) - s )) s | $(grep -Eo "[0-9]+ assertions? in [0-9]+ test cases?" "$3/test_$name.log" | tail -1) |"
  ' _ {} "$tests" "$logs" <<<"$tags" >"$logs/tests.md"
  echo "| test file | result | wall | checks |"
  echo "|---|---|---|---|"
  sort "$logs/tests.md"
  if grep -q FAILED "$logs/tests.md"; then
    status=1
    for f in $(grep FAILED "$logs/tests.md" | cut -d'|' -f2); do
      echo
      echo "### $f (the end of its log)"
      echo '```'
      tail -n 40 "$logs/test_$f.log"
      echo '```'
    done
  fi
  echo
  echo "Test tier: $(( $(date +%s) - t0 )) s wall, $jobs processes at once."
fi

[ "${BENCH:-1}" != 0 ] || exit $status
echo
echo "## Benchmark: $device, $driver"
echo
echo "$frames frames a row after the scene loads; ms are means over those frames but the first (its"
echo "program builds and first allocations are paid once). Solver: the"
echo "GPU solver's frame (every substep and the collision passes) timed to completion. Drawn:"
echo "the same plus drawing the frame at 1920x1080 (shadows, deep opacity maps, Kajiya-Kay),"
echo "the renderer's own GPU time; fps = 1000 / (solver + drawing)."
echo
echo "| scene | collision | strands | particles | kernels | drawn | solver ms | solver p95 | drawing ms | ms a frame | fps |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
row() {  # row LABEL PRESET MODE DRAW KERNELS
  local label=$1 preset=$2 mode=$3 draw=$4 kernels=$5 m="$logs/metrics.json"
  local args=(--headless --quiet --frames "$frames" --metrics "$m" --set "collision.mode=$mode"
              "${scene_args[@]}")
  if [ "$draw" = yes ]; then args+=(--size 1920x1080); else args+=(--no-render); fi
  rm -f "$m"
  local env=()
  [ "$kernels" = auto ] || env=(CSM_GPU_KERNELS="$kernels")
  if ! env "${env[@]}" "$bin" "$preset" "${args[@]}" >"$logs/run.log" 2>&1; then
    echo "| $label | $mode | | | $kernels | $draw | run failed: $(tail -n1 "$logs/run.log" | tr '|' '/') |"
    status=1
    return
  fi
  python3 - "$m" "$label" "$mode" "$draw" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
ms = m["ms"]
# Steady: the first frame (program builds, first allocations) left out where the build says it.
sim, p95 = ms.get("sim_steady", ms["sim_mean"]), ms["sim_p95"]
draw = ms.get("render_steady", ms.get("render_mean", 0.0)) if sys.argv[4] == "yes" else 0.0
total = sim + draw
fps = 1000.0 / total if total > 0 else 0.0
drawn = f"{draw:.2f}" if sys.argv[4] == "yes" else "-"
where = "1080p" if sys.argv[4] == "yes" else "no"
kernels = m.get("solver_variant") or "?"
strands = m.get("strands", "?")
if m.get("groom_strands", strands) != strands:
    strands = f"{strands} of {m['groom_strands']}"
print(f"| {sys.argv[2]} | {sys.argv[3]} | {strands} | {m['particles']} | {kernels} | "
      f"{where} | {sim:.2f} | {p95:.2f} | {drawn} | {total:.2f} | {fps:.3g} |")
PY
}
declare -A scenes=([default]="default:$root/presets/default.json"
  [fig1]="Fig. 1:$root/presets/paper_fig1_straight.json"
  [fig3]="Fig. 3:$root/presets/paper_fig3_curly.json"
  [groom]="groom ${GROOM_STRANDS:-100000}:$root/presets/default.json")
for name in ${SCENES:-default fig1 fig3}; do
  scene=${scenes[$name]:-}
  [ -n "$scene" ] || { echo "gpu_check: SCENES: no scene $name" >&2; exit 1; }
  scene_args=()
  if [ "$name" = groom ]; then
    groom=$logs/groom.hair
    grow=(--set hairstyle.strands="${GROOM_STRANDS:-100000}" --set hairstyle.particles_per_strand=32)
    "$bin" --headless --no-render --quiet --solver cpu --frames 0 "${grow[@]}" \
      --export-hair "$groom" >"$logs/groom.log" 2>&1 ||
      { echo "gpu_check: the groom could not be made: $(tail -n1 "$logs/groom.log")" >&2; exit 1; }
    scene_args=("${grow[@]}" --set hairstyle.file="$groom" --set render.children=0)
  fi
  for mode in ${MODES:-off head volume strands volume+strands}; do
    for draw in ${DRAW:-no yes}; do
      for kernels in ${KERNELS:-strand particle}; do
        row "${scene%%:*}" "${scene#*:}" "$mode" "$draw" "$kernels"
      done
    done
  done
done
echo
echo "gpu_check: $([ $status -eq 0 ] && echo "all passed" || echo "FAILURES above"); logs in $logs"
exit $status
