#!/usr/bin/env bash
# Builds csmhair and runs every test (CPU, GPU on the real GL driver, images, command line,
# the window under Xvfb), then the fuzz targets' short run (scripts/fuzz.sh short: clang,
# libFuzzer, ASan and UBSan, in build-fuzz/; CSM_SKIP_FUZZ=1 leaves it out).
#   scripts/test.sh [ctest arguments...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh" "$root/build"
cd "$root/build"
ctest --output-on-failure --timeout 1200 "$@"
if [ "${CSM_SKIP_FUZZ:-0}" != 1 ]; then
  bash "$root/scripts/fuzz.sh" short
fi
