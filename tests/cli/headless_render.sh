#!/usr/bin/env bash
# Headless capture end to end: PNG frames of the requested size, --every, the render timings in
# the metrics, and --video through the real ffmpeg (read back by ffprobe) or a clear message
# when ffmpeg is missing.
set -eu
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
preset="$src/presets/paper_fig1_straight.json"
# Fewer strands than the preset's 10,000 so the CPU reference keeps the test short.
few=(--solver cpu --set hairstyle.strands=1500 --quiet)

"$bin" "$preset" --headless --frames 3 --out "$tmp/out" --size 320x180 "${few[@]}" \
  --metrics "$tmp/m.json"
"$bin" "$preset" --headless --frames 4 --every 2 --out "$tmp/every" --size 64x48 "${few[@]}"

python3 - "$tmp" <<'PY'
import json, os, struct, sys
tmp = sys.argv[1]
def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", path + ": not a PNG"
    assert head[12:16] == b"IHDR", path
    return struct.unpack(">II", head[16:24])
frames = sorted(os.listdir(os.path.join(tmp, "out")))
assert frames == ["frame_00001.png", "frame_00002.png", "frame_00003.png"], frames
for f in frames:
    assert png_size(os.path.join(tmp, "out", f)) == (320, 180), f
every = sorted(os.listdir(os.path.join(tmp, "every")))
assert every == ["frame_00001.png", "frame_00002.png"], every
assert png_size(os.path.join(tmp, "every", every[0])) == (64, 48)
# Not blank: a PNG of one colour compresses to almost nothing.
assert os.path.getsize(os.path.join(tmp, "out", frames[0])) > 20000
m = json.load(open(os.path.join(tmp, "m.json")))
ms = m["ms"]
print("render ms", ms["render_mean"], ms["render_stages"], "drawn", m["drawn_strands"])
assert ms["render_mean"] > 0
# The first frame (program builds) apart: the mean is the first and the steady frames together.
assert ms["render_first"] > 0 and ms["render_steady"] > 0
mean3 = (ms["render_first"] + 2 * ms["render_steady"]) / 3
assert abs(mean3 - ms["render_mean"]) <= 1e-6 * ms["render_mean"], (mean3, ms)
sim_mean3 = ms["sim_steady"] * 2 / 3
assert 0 < sim_mean3 < ms["sim_mean"], ms
for stage in ["shadow", "head", "hair"]:
    assert ms["render_stages"][stage] >= 0, stage
assert m["drawn_strands"] == 1500 and m["render_size"] == [320, 180]
PY

# --video without ffmpeg: exit 1 before simulating, saying so.
set +e
out=$(env PATH=/nonexistent "$bin" "$preset" --headless --frames 1 --video "$tmp/v.mp4" \
  "${few[@]}" 2>&1)
status=$?
set -e
echo "$out"
[ "$status" -eq 1 ] || { echo "FAIL: --video without ffmpeg exited $status"; exit 1; }
grep -q "ffmpeg, which is not installed" <<<"$out" || { echo "FAIL: no clear message"; exit 1; }

# --video through the real ffmpeg (scripts/setup.sh installs it), read back by its ffprobe: the
# frames asked for, of the size asked for (an odd side rounded down to even for yuv420p).
command -v ffprobe >/dev/null || { echo "FAIL: ffmpeg/ffprobe not installed (scripts/setup.sh)"; exit 1; }
"$bin" "$preset" --headless --frames 12 --video "$tmp/v.mp4" --size 161x90 "${few[@]}"
probe=$(ffprobe -v error -select_streams v:0 -count_frames \
  -show_entries stream=codec_name,width,height,nb_read_frames -of csv=p=0 "$tmp/v.mp4")
echo "ffprobe: $probe"
[ "$probe" = "h264,160,90,12" ] || { echo "FAIL: expected h264,160,90,12 from ffprobe"; exit 1; }
echo "ok"
