#!/usr/bin/env bash
# The mannequin's face from the front, three-quarter and side, drawn by the headless command,
# beside other heads drawn the same way: each OBJ given becomes a row (a real scan, or an
# earlier mannequin written out as a mesh); the built-in mannequin's row first, or where the word
# "mannequin" stands among them.
#   scripts/face_figure.sh OUT.png [BUILD_DIR] [LABEL=HEAD.obj | mannequin ...]
# e.g. scripts/face_figure.sh docs/images/face.png build scan=/path/LeePerrySmith.obj
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$1
bin=${2:-"$root/build"}/app/csmhair
shift $(($# >= 2 ? 2 : 1))
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$root"

views=("front 0" "three-quarter 35" "side 90")
row() {  # NAME [ARGS...]: the three views of one head
  local name=$1
  shift
  for v in "${views[@]}"; do
    local label=${v% *} yaw=${v#* }
    "$bin" presets/default.json --headless --quiet --frames 1 --every 1 --size 400x460 \
      --set hairstyle.strands=1 --set hairstyle.scalp_angle=5 --set render.opacity=0.01 \
      --set camera.yaw="$yaw" \
      --set camera.pitch=0 --set camera.distance=0.46 --set camera.target=0,-0.04,0.02 \
      "$@" --out "$tmp/$name-$label"
  done
}
[[ " $* " == *" mannequin "* ]] || set -- mannequin "$@"
rows=()
for spec in "$@"; do
  name=${spec%%=*}
  if [ "$spec" = mannequin ]; then
    row mannequin
  else
    row "$name" --set head.mesh="${spec#*=}"
  fi
  rows+=("$name")
done
/usr/bin/python3 - "$tmp" "$out" "${rows[@]}" <<'PY'
import sys
import matplotlib.image as image
import numpy as np
tmp, out, rows = sys.argv[1], sys.argv[2], sys.argv[3:]
views = ["front", "three-quarter", "side"]
grid = [np.concatenate([image.imread(f"{tmp}/{r}-{v}/frame_00001.png")[..., :3] for v in views],
                       axis=1) for r in rows]
image.imsave(out, np.concatenate(grid, axis=0))
PY
echo "$out: rows ${rows[*]}; columns front, three-quarter, side"
