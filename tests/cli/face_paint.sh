#!/usr/bin/env bash
# The mannequin's painted eyes: drawn close up with render.iris_color red and then blue, the two
# pictures differ only in a disc about the eye's centre (the iris), whose middle (the pupil) is
# dark in both; a head of the user's own (head.mesh, here a sphere) is drawn unpainted, the same
# whatever the iris colour.
set -u
bin=$1
REPO=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# A UV sphere of radius 0.1 m about the origin.
/usr/bin/python3 - "$tmp/head.obj" <<'PY'
import math, sys
stacks, slices, r = 24, 32, 0.1
out = ["v 0 %.6f 0" % r]
for i in range(1, stacks):
    t = math.pi * i / stacks
    for j in range(slices):
        p = 2 * math.pi * j / slices
        out.append("v %.6f %.6f %.6f" % (r * math.sin(t) * math.sin(p), r * math.cos(t),
                                          r * math.sin(t) * math.cos(p)))
out.append("v 0 %.6f 0" % -r)
ring = lambda i, j: 2 + (i - 1) * slices + j % slices
for j in range(slices):
    out.append("f 1 %d %d" % (ring(1, j), ring(1, j + 1)))
for i in range(1, stacks - 1):
    for j in range(slices):
        out.append("f %d %d %d %d" % (ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)))
last = 2 + (stacks - 1) * slices
for j in range(slices):
    out.append("f %d %d %d" % (ring(stacks - 1, j), last, ring(stacks - 1, j + 1)))
open(sys.argv[1], "w").write("\n".join(out) + "\n")
PY

# Looking straight at the right eye (sim/head/mannequin.h kMannequinFace) from 8 cm.
view=(--headless --quiet --frames 1 --every 1 --size 200x200 --set hairstyle.strands=1
      --set render.opacity=0.01 --set camera.yaw=0 --set camera.pitch=0
      --set camera.distance=0.08 --set camera.target=0.0315,-0.0135,0.0595)
for head in mannequin mesh; do
  extra=()
  [ "$head" = mesh ] && extra=(--set head.mesh="$tmp/head.obj")
  for colour in 1,0,0 0,0,1; do
    "$bin" "$REPO/presets/default.json" "${view[@]}" "${extra[@]}" \
      --set render.iris_color=$colour --out "$tmp/$head-$colour" >/dev/null || exit 1
  done
done
/usr/bin/python3 - "$tmp" <<'PY'
import sys
import matplotlib.image as image
import numpy as np
tmp = sys.argv[1]
read = lambda name: image.imread(f"{tmp}/{name}/frame_00001.png")[..., :3].astype(float)
red, blue = read("mannequin-1,0,0"), read("mannequin-0,0,1")
differs = np.abs(red - blue).sum(axis=-1) > 0.05
ys, xs = np.nonzero(differs)
print(f"mannequin: {differs.sum()} pixels differ, rows {ys.min()}-{ys.max()}, "
      f"columns {xs.min()}-{xs.max()}")
# The iris: a disc some 40 pixels across (5.6 mm at 8 cm), about the picture's centre.
assert 400 < differs.sum() < 4000, differs.sum()
assert abs(ys.mean() - 100) < 15 and abs(xs.mean() - 100) < 15, (ys.mean(), xs.mean())
assert ys.max() - ys.min() < 70 and xs.max() - xs.min() < 70
# Red where red was asked for, blue where blue was.
assert red[differs][:, 0].mean() > red[differs][:, 2].mean() + 0.1
assert blue[differs][:, 2].mean() > blue[differs][:, 0].mean() + 0.1
# The pupil dark in both, the skin about the eye lighter.
centre = (slice(95, 106), slice(95, 106))
for picture in (red, blue):
    assert picture[centre].mean() < 0.2, picture[centre].mean()
    assert picture[160:, :].mean() > 0.3
mesh = np.abs(read("mesh-1,0,0") - read("mesh-0,0,1")).sum(axis=-1) > 0.05
print(f"head.mesh: {mesh.sum()} pixels differ")
assert mesh.sum() == 0
PY
