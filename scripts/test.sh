#!/usr/bin/env bash
# Builds csmhair and runs every test (CPU, GPU on the real GL driver, images, command line,
# the window under Xvfb).
#   scripts/test.sh [ctest arguments...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh" "$root/build"
cd "$root/build"
ctest --output-on-failure --timeout 1200 "$@"
