#!/usr/bin/env bash
# A dense groom through guides in the volume mode, against the same groom with every strand
# simulated, for one or more builds in one run: the default preset grown at 50,000 strands of
# 17 particles, 15-20 cm, out from the scalp (hairstyle.fall 0.3), collision.mode=volume, FRAMES
# frames (default 30) of its nodding, the GPU solver. Every strand simulated (hairstyle.guides 0)
# and through the automatic 4,000 guides, each written with --export-hair (every strand as
# drawn) and compared point by point: RMS, 99th percentile, largest, and the drawn points' mean
# height against the full groom's. Every build's full groom is compared with the first's too
# (every strand simulated should not change). With OUT, the last frame of the full groom and of
# each build's guided groom drawn at 480x270 side by side into OUT/guided_volume.png.
#   scripts/bench_guided_volume.sh FRAMES OUT|"" [LABEL=]BIN...
set -euo pipefail
frames=${1:-30}
out=${2:-}
shift 2
[ $# -ge 1 ] || { echo "bench_guided_volume: name at least one csmhair binary" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
groom=(--set hairstyle.strands=50000 --set hairstyle.particles_per_strand=17
       --set hairstyle.length_min=0.15 --set hairstyle.length_max=0.2 --set hairstyle.fall=0.3
       --set collision.mode=volume)
run=(--headless --solver gpu --quiet "${groom[@]}" --frames "$frames")
echo "Load before: $(uptime | sed 's/.*load average: //')"
k=0
labels=()
for arg in "$@"; do
  k=$((k + 1))
  bin=${arg#*=}
  labels+=("${arg%%=*}")
  "$bin" "${run[@]}" --no-render --set hairstyle.guides=0 --export-hair "$tmp/full$k.hair"
  "$bin" "${run[@]}" --no-render --export-hair "$tmp/guided$k.hair"
  if [ -n "$out" ]; then
    if [ "$k" = 1 ]; then
      "$bin" "${run[@]}" --set hairstyle.guides=0 --size 480x270 --every "$frames" --out "$tmp/pfull"
    fi
    "$bin" "${run[@]}" --size 480x270 --every "$frames" --out "$tmp/p$k"
  fi
done
echo "Load after: $(uptime | sed 's/.*load average: //')"
/usr/bin/python3 - "$tmp" "$out" "$frames" "$(cd "$(dirname "$0")" && pwd)" "${labels[@]}" <<'PY'
import glob, sys
import numpy as np
sys.path.insert(0, sys.argv[4])
import hair_file
tmp, out, frames, bins = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[5:]

def read(path):
    return hair_file.read(path)[0].astype(np.float64)

full = read(f"{tmp}/full1.hair")
print()
print(f"50,000 strands of 17 particles, 15-20 cm, volume mode, {frames} frames of nodding; "
      "the drawn points through 4,000 guides against every strand simulated")
print()
print("| build, through 4,000 guides | RMS mm | 99th percentile mm | largest mm | mean height mm (full groom's) | every strand simulated, against the first build's |")
print("|---|---|---|---|---|---|")
for k, bin in enumerate(bins, 1):
    g, f = read(f"{tmp}/guided{k}.hair"), read(f"{tmp}/full{k}.hair")
    d = np.linalg.norm(g - full, axis=1) * 1e3
    same = "same" if np.array_equal(f, full) else f"{np.abs(f - full).max() * 1e3:.3f} mm apart"
    print(f"| {bin} | {np.sqrt(np.mean(d * d)):.2f} | {np.percentile(d, 99):.2f} | {d.max():.1f} | "
          f"{g[:, 1].mean() * 1e3:.1f} ({full[:, 1].mean() * 1e3:.1f}) | {same} |")
if out:
    from PIL import Image, ImageDraw
    pictures = [("every strand simulated", sorted(glob.glob(f"{tmp}/pfull/*.png"))[-1])]
    for k, bin in enumerate(bins, 1):
        pictures.append((f"through 4,000 guides: {bin}", sorted(glob.glob(f"{tmp}/p{k}/*.png"))[-1]))
    images = [Image.open(p).convert("RGB") for _, p in pictures]
    w, h = images[0].size
    sheet = Image.new("RGB", (w * len(images), h + 18), "white")
    draw = ImageDraw.Draw(sheet)
    for i, (im, (label, _)) in enumerate(zip(images, pictures)):
        sheet.paste(im, (i * w, 18))
        draw.text((i * w + 4, 3), label[-60:], fill="black")
    sheet.save(f"{out}/guided_volume.png")
    print(f"\n{out}/guided_volume.png")
PY
