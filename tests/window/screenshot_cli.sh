#!/usr/bin/env bash
# csmhair PRESET --screenshot FILE --exit-after N in a window, end to end: the PNG is written
# with the window's size, and a missing display is reported with a pointer to --headless.
set -u
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

# No display: says so, points to --headless, exit 1.
out=$(env -u DISPLAY -u WAYLAND_DISPLAY "$bin" "$src/presets/short_shake.json" 2>&1)
status=$?
if [ $status -ne 1 ] || ! grep -q -- "--headless" <<<"$out"; then
  echo "FAIL: without a display: exit $status, output: $out"; fail=1
else
  echo "ok: without a display -> 1: $out"
fi

run() { bash "$src/tests/window/run_xvfb.sh" "$@"; }

run "$bin" "$src/presets/short_shake.json" --size 800x600 --set hairstyle.strands=800 \
    --screenshot "$tmp/shot.png" --exit-after 5 --metrics "$tmp/m.json" >"$tmp/log" 2>&1
status=$?
cat "$tmp/log"
if [ $status -ne 0 ]; then echo "FAIL: --screenshot run exited $status"; fail=1; fi
size=$(python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(24); print(*struct.unpack('>II', d[16:24]))" "$tmp/shot.png" 2>/dev/null)
if [ "$size" != "800 600" ]; then echo "FAIL: screenshot size '$size', expected '800 600'"; fail=1
else echo "ok: screenshot 800x600"; fi
grep -q "5 simulated frames" "$tmp/log" || { echo "FAIL: no frame summary"; fail=1; }
# --metrics from the window: the UI's frame intervals and the simulation's frames.
if python3 - "$tmp/m.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
ms = m["ms"]
assert m["mode"] == "window", m["mode"]
assert m["frames"] == 5 and m["sim_frames"] == 5, (m["frames"], m["sim_frames"])
assert ms["ui_frames"] >= 1 and ms["ui_p95"] >= ms["ui_mean"] * 0.5 > 0, ms
assert ms["sim_mean"] > 0 and m["accuracy"]["samples"] >= 1, (ms, m["accuracy"])
assert m["strands"] == 800, m["strands"]
print("ok: window metrics: ui_mean %.1f ms, ui_p95 %.1f ms over %d UI frames; sim %.1f ms"
      % (ms["ui_mean"], ms["ui_p95"], ms["ui_frames"], ms["sim_mean"]))
PY
then :; else echo "FAIL: window --metrics"; cat "$tmp/m.json"; fail=1; fi

# A broken preset opens the window anyway, shows the messages, and exits 2 when scripted.
printf '{"sim": {"substeps": 0}}' >"$tmp/bad.json"
run "$bin" "$tmp/bad.json" --screenshot "$tmp/bad.png" --exit-after 2 >"$tmp/log" 2>&1
status=$?
if [ $status -ne 2 ] || [ ! -s "$tmp/bad.png" ] || ! grep -q "sim.substeps" "$tmp/log"; then
  echo "FAIL: broken preset: exit $status"; cat "$tmp/log"; fail=1
else
  echo "ok: broken preset -> 2, window shown with its messages"
fi
exit $fail
