#!/usr/bin/env bash
# Builds csmhair and runs it on the default preset: the window when there is a display,
# otherwise a headless capture into out/ (frames as PNG, metrics as JSON).
#   scripts/run.sh [csmhair arguments...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh" "$root/build"
bin="$root/build/app/csmhair"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$bin" "$@"
fi
echo "run: no display; capturing headless into $root/out (the window needs a display)" >&2
mkdir -p "$root/out"
exec "$bin" --headless --frames 120 --every 30 --out "$root/out" --metrics "$root/out/metrics.json" "$@"
