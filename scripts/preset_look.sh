#!/usr/bin/env bash
# How far each preset's look moves between two builds: every preset run for 2 s by both
# (CPU solver, 300 strands, head collisions only, so that strands are independent and the
# comparison is not chaotic), once with the head still and no wind (the hairstyle) and once
# with the preset's own motion and wind; the tips compared, mean / median / max / RMS in mm.
#   scripts/preset_look.sh OLD_BIN NEW_BIN [PRESET.json...]
# OLD_PRESETS=DIR: the old build reads the preset of the same name from DIR (presets written
# for a later build can hold keys an older one refuses), e.g. from
#   mkdir old && git archive REV presets | tar -x -C old   (then OLD_PRESETS=old/presets)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$1 new=$2
shift 2
[ $# -gt 0 ] || set -- "$root"/presets/*.json
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
base=(--headless --no-render --quiet --solver cpu --frames 120 --set hairstyle.strands=300
      --set collision.mode=head)
still=(--set head.motion=none --set wind.strength=0)
echo "| preset | still: tips move, mean / median / max / RMS (mm) | moving: mean / median / max / RMS (mm) |"
echo "|---|---|---|"
for preset in "$@"; do
  row="| $(basename "$preset" .json) |"
  for mode in still moving; do
    extra=()
    [ $mode = moving ] || extra=("${still[@]}")
    oldPreset=$preset
    [ -z "${OLD_PRESETS:-}" ] || oldPreset="$OLD_PRESETS/$(basename "$preset")"
    "$old" "$oldPreset" "${base[@]}" "${extra[@]}" --export-hair "$tmp/old.hair"
    "$new" "$preset" "${base[@]}" "${extra[@]}" --export-hair "$tmp/new.hair"
    row+=" $(python3 "$root/scripts/hair_tips.py" "$tmp/old.hair" "$tmp/new.hair") |"
  done
  echo "$row"
done
