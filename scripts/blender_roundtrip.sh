#!/usr/bin/env bash
# A simulated frame back into Blender: csmhair exports the default preset's last frame as OBJ
# curves (--export-hair FRAME.obj), Blender imports it in batch mode with its own OBJ importer
# and counts the strands (scripts/blender_hair_import.py), which must be as many as were
# simulated. The way back of scripts/blender_groom.sh; Blender is not needed to build or test
# csmhair (on Debian 12: apt-get install blender, 3.4).
#   scripts/blender_roundtrip.sh [CSMHAIR] [FRAMES] [csmhair options...]
#   (default build/app/csmhair, 10 frames, the CPU solver)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/app/csmhair}
frames=${2:-10}
shift $(( $# > 2 ? 2 : $# ))
if ! command -v blender >/dev/null; then
  echo "blender_roundtrip: no blender on PATH; on Debian 12: apt-get install blender (3.4)" >&2
  exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" --headless --no-render --quiet --solver cpu --frames "$frames" \
  --export-hair "$tmp/frame.obj" --metrics "$tmp/m.json" "$@"
strands=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["strands"])' "$tmp/m.json")
echo "csmhair: $strands strands in $tmp/frame.obj ($(du -h "$tmp/frame.obj" | cut -f1))"
status=0
blender -b --factory-startup --python-exit-code 1 --python "$root/scripts/blender_hair_import.py" -- \
  "$tmp/frame.obj" "$strands" >"$tmp/blender.log" 2>&1 || status=$?
grep -E "blender_hair_import|Error" "$tmp/blender.log" || tail -n 20 "$tmp/blender.log"
exit $status
