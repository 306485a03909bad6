#!/usr/bin/env bash
# Makes the README's pictures (docs/images) with the headless command, on whatever GL driver
# is present (Mesa llvmpipe without a GPU): the default preset, close-ups of its hairline and
# parting, its children off beside on, the paper's two scenes, an imported groom, the
# mannequin, and the window under Xvfb.
#   scripts/make_images.sh [BUILD_DIR]      (default: build)
# ONLY="fig3 imported" makes just those (default, hairline, parting, children, mannequin, fig1,
# fig3, imported, shoulders, viewer).
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
# Close-ups of the default preset: the hairline from the front, the parting from above.
shot hairline presets/default.json 60 --size 960x600 --set camera.pitch=12 --set camera.yaw=-20 \
  --set camera.distance=0.32 --set camera.target=0,0.04,0.04
shot parting presets/default.json 60 --size 960x600 --set camera.pitch=60 --set camera.yaw=0 \
  --set camera.distance=0.36 --set camera.target=0,0.07,0
# Children off (the 3,000 simulated strands alone) beside on (render.children 6: 21,000).
if want children; then
  for n in 0 6; do
    "$bin" presets/default.json --headless --quiet --frames 60 --every 60 --size 640x540 \
      --set render.children=$n --set camera.distance=0.55 --out "$tmp/children$n"
  done
  /usr/bin/python3 - "$tmp/children0/frame_00001.png" "$tmp/children6/frame_00001.png" \
    "$out/children.png" <<'PY'
import sys
import matplotlib.image as image
import numpy as np
a, b = image.imread(sys.argv[1]), image.imread(sys.argv[2])
image.imsave(sys.argv[3], np.concatenate([a, b], axis=1))
PY
  echo "docs/images/children.png"
fi
# The mannequin alone, three-quarter view.
shot mannequin presets/default.json 1 --size 800x800 --set hairstyle.strands=1 --set render.opacity=0.01 \
  --set camera.yaw=25 --set camera.pitch=0 --set camera.distance=0.42 \
  --set camera.target=0,-0.03,0
shot fig1 presets/paper_fig1_straight.json 60 --solver cpu
shot fig3 presets/paper_fig3_curly.json 40 --set camera.target=0,-0.13,0 \
  --set camera.distance=0.85
# An imported groom: a cyHair file written by another run (4,000 strands of Fig. 3's curls at
# rest), read back as a groom file with the default settings, on the mannequin, in the
# file's own scale (it was made in this head frame).
want imported && "$bin" presets/paper_fig3_curly.json --headless --quiet --frames 0 --no-render \
  --set hairstyle.strands=4000 --export-hair "$tmp/groom.hair"
shot imported "$tmp/groom.hair" 60 --set collision.head_shape=sdf --set hairstyle.import_scale=1
# The shoulders under a clip whose head turns 80 degrees while the chest stays (the project's
# turn_mixed.bvh): long hair from behind and above, at rest (0.83 s), half way (1.67 s) and at the
# turn (2.5 s), side by side.
if want shoulders; then
  python3 scripts/make_clips.py "$tmp/clips" >/dev/null
  "$bin" presets/long_windy.json --headless --quiet --frames 150 --every 50 --size 560x560 \
    --set motion.clip="$tmp/clips/turn_mixed.bvh" --set hairstyle.strands=2000 \
    --set collision.mode=volume --set wind.strength=0 --set camera.yaw=15 \
    --set camera.pitch=40 --set camera.distance=1.0 --set camera.target=0,-0.2,0 \
    --out "$tmp/shoulders"
  /usr/bin/python3 - "$tmp/shoulders" "$out/shoulders.png" <<'PY'
import sys
import matplotlib.image as image
import numpy as np
frames = [image.imread(f"{sys.argv[1]}/frame_{k:05d}.png")[..., :3] for k in (1, 2, 3)]
image.imsave(sys.argv[2], np.concatenate(frames, axis=1))
PY
  echo "docs/images/shoulders.png"
fi
want viewer || exit 0
xvfb-run -a -s "-screen 0 1600x900x24" "$bin" presets/default.json --size 1600x900 \
  --screenshot "$out/viewer.png" --exit-after 30
echo "docs/images/viewer.png"
