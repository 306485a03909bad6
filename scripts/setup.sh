#!/usr/bin/env bash
# Installs what csmhair needs from Debian 12's packages (only what is missing), then
# configures and builds it. Quick when everything is already there.
#   scripts/setup.sh [BUILD_DIR]      (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}

packages=(
  cmake g++ make pkg-config
  libeigen3-dev libglm-dev nlohmann-json3-dev catch2
  libglfw3-dev libepoxy-dev libegl-dev libgl-dev libimgui-dev libpng-dev
  libtinyobjloader-dev           # OBJ heads (head.mesh)
  libegl-mesa0 libgl1-mesa-dri   # Mesa: llvmpipe where there is no GPU
  xvfb xauth                     # the window under a virtual display (tests, no-display runs)
  python3 python3-matplotlib     # test scripts and benchmark charts
  ffmpeg                         # headless --video (its ffprobe reads the file back in the tests)
  iwyu                           # include-what-you-use: no include of ours a file does not use
  slurm-wlm munge                # the render farm's scheduler (scripts/farm; its test runs one)
)
# shellcheck source=scripts/packages.sh
source "$root/scripts/packages.sh"
install_missing setup "${packages[@]}"

jobs=$(nproc 2>/dev/null || echo 2)
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j "$jobs"
