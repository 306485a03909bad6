#!/usr/bin/env bash
# Makes a groom with Blender in batch mode (scripts/blender_groom.py: hair on a head-sized
# sphere, fallen under gravity, written as an OBJ of edge chains) and simulates it headless:
# the path from an artist's tool to csmhair. Blender is not needed to build or test csmhair.
#   scripts/blender_groom.sh [OUT_DIR]      (default: out/blender)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-"$root/out/blender"}
bin="$root/build/app/csmhair"
if ! command -v blender >/dev/null; then
  echo "blender_groom: no blender on PATH; on Debian 12: apt-get install blender (3.4)" >&2
  exit 1
fi
if [ ! -x "$bin" ]; then
  echo "blender_groom: no $bin; build it first: bash scripts/setup.sh" >&2
  exit 1
fi
mkdir -p "$out"
blender -b --factory-startup --python-exit-code 1 --python "$root/scripts/blender_groom.py" \
  -- "$out/groom.obj"
"$bin" "$out/groom.obj" --headless --frames 60 --every 60 --out "$out"
echo "$out/frame_00001.png"
