#!/usr/bin/env bash
# Makes the README's pictures (docs/images) with the headless command, on whatever GL driver
# is present (Mesa llvmpipe without a GPU): the default preset, the paper's two scenes, an
# imported groom, and the window under Xvfb.
#   scripts/make_images.sh [BUILD_DIR]      (default: build)
# ONLY="fig3 imported" makes just those (default, fig1, fig3, imported, viewer).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build"}/app/csmhair
out="$root/docs/images"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
want() { [ -z "${ONLY:-}" ] || [[ " $ONLY " == *" $1 "* ]]; }
shot() {  # NAME PRESET FRAMES [ARGS...]: the last frame of a headless run, as NAME.png
  local name=$1 preset=$2 frames=$3
  want "$name" || return 0
  shift 3
  "$bin" "$preset" --headless --quiet --frames "$frames" --every "$frames" --out "$tmp/$name" "$@"
  cp "$tmp/$name/frame_00001.png" "$out/$name.png"
  echo "docs/images/$name.png"
}
cd "$root"
shot default presets/default.json 90
shot fig1 presets/paper_fig1_straight.json 60 --solver cpu
shot fig3 presets/paper_fig3_curly.json 40 --set camera.target=0,-0.13,0 \
  --set camera.distance=0.85
# An imported groom: a cyHair file written by another run (4,000 strands of Fig. 3's curls at
# rest), read back as a groom file with the default settings, on the mannequin, in the
# file's own scale (it was made in this head frame).
want imported && "$bin" presets/paper_fig3_curly.json --headless --quiet --frames 0 --no-render \
  --set hairstyle.strands=4000 --export-hair "$tmp/groom.hair"
shot imported "$tmp/groom.hair" 60 --set collision.head_shape=sdf --set hairstyle.import_scale=1
want viewer || exit 0
xvfb-run -a -s "-screen 0 1600x900x24" "$bin" presets/default.json --size 1600x900 \
  --screenshot "$out/viewer.png" --exit-after 30
echo "docs/images/viewer.png"
