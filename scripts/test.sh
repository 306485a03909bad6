#!/usr/bin/env bash
# Runs the tests, in one of two tiers:
#   scripts/test.sh [ctest arguments...]   everything (what CI runs): installs what is missing and
#                                          builds (scripts/setup.sh), runs every test (CPU, GPU on
#                                          the real GL driver, images, command line, the window
#                                          under Xvfb) as many at once as there are cores, then
#                                          the fuzz targets' short run (scripts/fuzz.sh short:
#                                          clang, libFuzzer, ASan and UBSan, in build-fuzz/;
#                                          CSM_SKIP_FUZZ=1 leaves it out)
#   scripts/test.sh quick [ctest args...]  the run after every edit, on a built tree: builds what
#                                          changed (no package installs), then the tests labelled
#                                          `quick` (the fast cases of every tier); no fuzzing
# CSM_TEST_JOBS sets how many tests run at once (default: the cores).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build"
jobs=${CSM_TEST_JOBS:-$(nproc 2>/dev/null || echo 2)}
if [ "${1:-}" = quick ]; then
  shift
  if [ ! -f "$build/CMakeCache.txt" ]; then
    echo "test.sh quick: no build in $build; run scripts/test.sh (or scripts/setup.sh) once" >&2
    exit 2
  fi
  cmake --build "$build" -j "$jobs"
  cd "$build"
  exec ctest --output-on-failure --timeout 600 -j "$jobs" -L quick "$@"
fi
"$root/scripts/setup.sh" "$build"
cd "$build"
ctest --output-on-failure --timeout 1200 -j "$jobs" "$@"
if [ "${CSM_SKIP_FUZZ:-0}" != 1 ]; then
  bash "$root/scripts/fuzz.sh" short
fi
