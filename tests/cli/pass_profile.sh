#!/usr/bin/env bash
# CSM_PASS_PROFILE=1: a headless run ends with its compute passes' ms a frame, one row a shader
# and the sum (gl/pass_profile.h); the strand contacts' passes appear in a strand mode, the
# penalty model's with collision.contact_model = penalty, the renderer's when it draws; without
# the variable, no table.
set -u
bin=$1
src=$2
. "$(dirname "$0")/lib/expect.sh"

run=(--headless --no-render --quiet --frames 2 --set hairstyle.strands=40)
CSM_PASS_PROFILE=1 expect 0 "csmhair: CSM_PASS_PROFILE, 2 frames" -- "${run[@]}"
CSM_PASS_PROFILE=1 expect 0 "| all passes |" -- "${run[@]}" --set collision.mode=head
CSM_PASS_PROFILE=1 expect 0 "| sim/candidates.comp |" -- "${run[@]}" --set collision.mode=strands
CSM_PASS_PROFILE=1 expect 0 "| sim/contact_solve.comp |" -- "${run[@]}" \
  --set collision.mode=strands
CSM_PASS_PROFILE=1 expect 0 "| sim/contact_penalty.comp |" -- "${run[@]}" \
  --set collision.mode=strands --set collision.contact_model=penalty
# The renderer's compute passes, drawn frames: the spline points, the children, the followers.
CSM_PASS_PROFILE=1 expect 0 "| render/hair_points.comp |" -- --headless --quiet --frames 2 \
  --every 2 --size 64x36 --set hairstyle.strands=40 --out "$(mktemp -d)"
CSM_PASS_PROFILE=1 expect 0 "| render/hair_followers.comp |" -- --headless --quiet --frames 2 \
  --every 2 --size 64x36 --set hairstyle.strands=40 --set hairstyle.guides=10 --out "$(mktemp -d)"
# Unset or 0: nothing printed.
out=$("$bin" "${run[@]}" 2>&1)
if grep -q "CSM_PASS_PROFILE" <<<"$out"; then echo "FAIL: a table without CSM_PASS_PROFILE"; fail=1; fi
out=$(CSM_PASS_PROFILE=0 "$bin" "${run[@]}" 2>&1)
if grep -q "CSM_PASS_PROFILE" <<<"$out"; then echo "FAIL: a table with CSM_PASS_PROFILE=0"; fail=1; fi
# The penalty model with the contacts' counterparts on the CPU solver runs too.
expect 0 "" -- "${run[@]}" --solver cpu --set collision.mode=strands \
  --set collision.contact_model=penalty
exit $fail
