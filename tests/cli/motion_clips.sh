#!/usr/bin/env bash
# Motion clips on the command line: the project's own clips (scripts/make_clips.py: a walk, a
# run with 6 channels on every joint, a head turn with mixed rotation orders, a jump, a jerky
# Z-up dance at 60 fps, a walk with a cut) each drive the default hairstyle without NaN, within
# the strain limit, nothing inside the head, no particle faster than the motion explains (the
# hair held rigidly, plus gravity over a strand's length and the wind: motion.dftl); the cut is carried; the units, axes and facing
# are inferred and said; a cm walk and a metre walk export the same world positions, which travel
# with the clip; --frames defaults to the clip's length; a truncated clip is refused with its line.
set -u
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$src/tests/cli/lib/expect.sh"
python3 "$src/scripts/make_clips.py" "$tmp/clips"
common=(--headless --no-render --solver cpu --set hairstyle.strands=200)

check() {  # check CLIP FRAMES CUTS [OPTION...]: run the clip, then its measures
  local clip=$1 frames=$2 cuts=$3
  "$bin" "$src/presets/default.json" "${common[@]}" "${@:4}" --set motion.clip="$tmp/clips/$clip" \
    --frames "$frames" --metrics "$tmp/$clip.json" 2>"$tmp/$clip.log" || {
    echo "FAIL: $clip: exit $?"; cat "$tmp/$clip.log"; fail=1; return; }
  python3 - "$tmp/$clip.json" "$clip" "$cuts" <<'PY' || fail=1
import json, sys
m = json.load(open(sys.argv[1]))
clip, cuts = sys.argv[2], int(sys.argv[3])
a = m["accuracy"]
bad = []
if a["nan_count"] != 0: bad.append("nan %d" % a["nan_count"])
if a["max_strain"] > 0.0501: bad.append("strain %.4f" % a["max_strain"])
if a["head_penetrations"] != 0: bad.append("%d particles in the head" % a["head_penetrations"])
if a["torso_penetrations"] != 0: bad.append("%d particles in the torso" % a["torso_penetrations"])
if a["max_speed"] > m["explained_peak_speed"]:
    bad.append("a particle at %.2f m/s, faster than the motion explains (%.2f: the rigid hair's peak %.2f, "
               "gravity and the wind)" % (a["max_speed"], m["explained_peak_speed"], m["rigid_peak_speed"]))
if m["motion"]["cuts_carried"] != cuts: bad.append("%d cuts carried, not %d" % (m["motion"]["cuts_carried"], cuts))
print(("FAIL: " if bad else "ok: ") + clip + ": strain %.4f, max speed %.2f m/s (rigid %.2f, explained %.2f), %d cuts %s"
      % (a["max_strain"], a["max_speed"], m["rigid_peak_speed"], m["explained_peak_speed"],
         m["motion"]["cuts_carried"], "; ".join(bad)))
sys.exit(1 if bad else 0)
PY
}

check walk_cm.bvh 90 0
check run_6ch.bvh 90 0
check turn_mixed.bvh 130 0
check jump.bvh 130 0
check dance_zup.bvh 120 0
check cut.bvh 130 1
# The GPU solver on a character that walks 9 m: its float positions round by 5e-7 m there, which
# the push out of the head once took for a particle out of reach and flung (9.5 m/s on the
# spheres, the CPU 2.2). Without DFTL, which would damp the fling, its fastest particle is the
# CPU's, give or take a tenth.
far=(--set hairstyle.strands=300 --set collision.mode=head --set collision.head_shape=spheres
  --set motion.dftl=0)
for solver in cpu gpu; do
  "$bin" "$src/presets/default.json" "${common[@]}" --solver $solver "${far[@]}" --quiet \
    --set motion.clip="$tmp/clips/walk_cm.bvh" --frames 360 --metrics "$tmp/far_$solver.json" ||
    { echo "FAIL: the far walk on $solver: exit $?"; fail=1; }
done
python3 - "$tmp/far_cpu.json" "$tmp/far_gpu.json" <<'PY' || fail=1
import json, sys
cpu, gpu = (json.load(open(p))["accuracy"]["max_speed"] for p in sys.argv[1:3])
ok = gpu <= 1.1 * cpu + 0.05
print(("ok" if ok else "FAIL") + ": the walk of 9 m, the fastest particle %.2f m/s on the GPU, %.2f on the CPU" % (gpu, cpu))
sys.exit(0 if ok else 1)
PY

# What was inferred, said.
grep -qF "cm (inferred: a skeleton 1.64 m tall), y up (inferred), facing +z (inferred)" "$tmp/walk_cm.bvh.log" \
  && echo "ok: the walk's units, axes and facing said" || { echo "FAIL: walk log"; cat "$tmp/walk_cm.bvh.log"; fail=1; }
grep -qF "CMU unit (inferred" "$tmp/dance_zup.bvh.log" && grep -qF "z up (inferred)" "$tmp/dance_zup.bvh.log" \
  && echo "ok: the dance's CMU units and z up said" || { echo "FAIL: dance log"; cat "$tmp/dance_zup.bvh.log"; fail=1; }
grep -qF "the clip cut 1 times" "$tmp/cut.bvh.log" && echo "ok: the cut said" || { echo "FAIL: cut log"; fail=1; }

# The same walk in cm and in metres: the same world positions, 2.1 m on after 1.5 s.
for unit in cm m; do
  "$bin" "$src/presets/default.json" "${common[@]}" --set hairstyle.strands=50 \
    --set motion.clip="$tmp/clips/walk_$unit.bvh" --frames 90 --export-hair "$tmp/walk_$unit.obj"
done
python3 - "$tmp/walk_cm.obj" "$tmp/walk_m.obj" <<'PY' || fail=1
import sys
def verts(p):
    return [tuple(map(float, l.split()[1:4])) for l in open(p) if l.startswith("v ")]
a, b = verts(sys.argv[1]), verts(sys.argv[2])
diff = max(max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a, b))
z = sum(p[2] for p in a) / len(a)
ok = len(a) == len(b) and diff < 2e-3 and abs(z - 2.1) < 0.15
print(("ok" if ok else "FAIL") + ": cm and m walks %d points, differ by %.2g m; the hair's mean z %.3f m (the clip: 2.1)" % (len(a), diff, z))
sys.exit(0 if ok else 1)
PY

# A clip plays through unless --frames says otherwise: 5 s at 60 frames a second.
expect 0 "300 frames" -- "$src/presets/default.json" --headless --no-render --solver cpu \
  --set hairstyle.strands=20 --set motion.clip="$tmp/clips/turn_mixed.bvh"
# A truncated clip, and one with a channel that does not exist: refused with the line.
head -n -3 "$tmp/clips/walk_cm.bvh" >"$tmp/truncated.bvh"
lines=$(wc -l <"$tmp/truncated.bvh")
expect 2 "motion.clip: $tmp/truncated.bvh:$lines: the file ends in frame 269 of 271" -- \
  "$src/presets/default.json" "${common[@]}" --set motion.clip="$tmp/truncated.bvh"
sed '5s/Zrotation/Zrot/' "$tmp/clips/walk_cm.bvh" >"$tmp/badchannel.bvh"
expect 2 "$tmp/badchannel.bvh:5: 'Zrot' is not a channel" -- \
  "$src/presets/default.json" "${common[@]}" --set motion.clip="$tmp/badchannel.bvh"
printf '{"motion": {"clip": "%s"}}\n' "$tmp/badchannel.bvh" >"$tmp/bad.json"
expect 2 "bad.json: motion.clip: $tmp/badchannel.bvh:5:" -- --validate "$tmp/bad.json"
exit $fail
