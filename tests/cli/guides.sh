#!/usr/bin/env bash
# Guides and followers end to end (hairstyle.guides): every strand simulated gives the same bytes
# however it is asked for (0, the auto default under its threshold, the strand count); a groom
# simulated through guides exports every strand as drawn, or its guides alone with
# --export-guides; and a 100,000-strand groom file imports at the auto default (4,000 guides),
# steps and comes back out at 100,000 strands.
set -u
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

# The strand count in a cyHair file's header.
strands() { python3 -c 'import struct,sys; print(struct.unpack_from("<I", open(sys.argv[1],"rb").read(), 4)[0])' "$1"; }

common=(--headless --no-render --quiet --solver cpu --frames 3 --set hairstyle.strands=400)
for g in 0 -1 400; do
  "$bin" "${common[@]}" --set hairstyle.guides=$g --export-hair "$tmp/all_$g.hair" ||
    { echo "FAIL: hairstyle.guides=$g did not run"; fail=1; }
done
for g in -1 400; do
  if cmp -s "$tmp/all_0.hair" "$tmp/all_$g.hair"; then
    echo "ok: hairstyle.guides=$g exports the bytes of hairstyle.guides=0"
  else
    echo "FAIL: hairstyle.guides=$g differs from every strand simulated"; fail=1
  fi
done

"$bin" "${common[@]}" --set hairstyle.guides=40 --export-hair "$tmp/drawn.hair" --metrics "$tmp/m.json" ||
  { echo "FAIL: 40 guides did not run"; fail=1; }
"$bin" "${common[@]}" --set hairstyle.guides=40 --export-guides --export-hair "$tmp/guides.hair" ||
  { echo "FAIL: --export-guides did not run"; fail=1; }
[ "$(strands "$tmp/drawn.hair")" = 400 ] && echo "ok: 40 guides export 400 strands as drawn" ||
  { echo "FAIL: the drawn export has $(strands "$tmp/drawn.hair") strands, not 400"; fail=1; }
[ "$(strands "$tmp/guides.hair")" = 40 ] && echo "ok: --export-guides writes the 40 guides" ||
  { echo "FAIL: --export-guides wrote $(strands "$tmp/guides.hair") strands, not 40"; fail=1; }
if cmp -s "$tmp/all_0.hair" "$tmp/drawn.hair"; then
  echo "FAIL: 40 guides exported what 400 simulated strands did"; fail=1
fi
python3 - "$tmp/m.json" <<'PY' || fail=1
import json, sys
m = json.load(open(sys.argv[1]))
run = m
ok = run["strands"] == 40 and run["groom_strands"] == 400
print(("ok" if ok else "FAIL") + ": metrics say %d simulated, %d drawn" % (run["strands"], run["groom_strands"]))
sys.exit(0 if ok else 1)
PY

# A 100,000-strand groom: grown at rest (the generator's strands; 4,000 of them simulated for the
# export), then imported as a file at the auto default.
"$bin" --headless --no-render --quiet --solver cpu --frames 0 --set hairstyle.strands=100000 \
  --set hairstyle.particles_per_strand=8 --export-hair "$tmp/big.hair" ||
  { echo "FAIL: no 100,000-strand groom"; fail=1; }
"$bin" --headless --no-render --quiet --solver cpu --frames 2 --set hairstyle.file="$tmp/big.hair" \
  --set hairstyle.strands=100000 --export-hair "$tmp/big_out.hair" --metrics "$tmp/big.json" ||
  { echo "FAIL: the 100,000-strand import did not run"; fail=1; }
[ "$(strands "$tmp/big_out.hair")" = 100000 ] && echo "ok: 100,000 strands in, 100,000 out" ||
  { echo "FAIL: the import came out at $(strands "$tmp/big_out.hair") strands"; fail=1; }
python3 - "$tmp/big.json" <<'PY' || fail=1
import json, sys
run = json.load(open(sys.argv[1]))
ok = run["strands"] == 4000 and run["groom_strands"] == 100000
print(("ok" if ok else "FAIL") + ": the import simulated %d strands, drew %d" % (run["strands"], run["groom_strands"]))
sys.exit(0 if ok else 1)
PY
exit $fail
