#!/usr/bin/env bash
# The step budget (sim.max_substeps) on a groom whose short strands ask for many steps: the flawed
# TressFX 4.x groom (scripts/make_flawed_groom.py: 2,228 strands x 32 points, 4 mm to 30 cm) at
# the default budget and at the steps it asks for (a budget of 64), the same FRAMES frames of the
# nodding motion. Prints ms a frame, steps, strands at alpha = 1, strain and head penetrations for
# each, and how far the budget moves the strands' points, by strand length (RMS, 99th percentile,
# largest); writes docs/charts/step_budget.csv and step_budget.png (and .svg).
#   scripts/bench_step_budget.sh BIN [FRAMES] [SOLVER]     (default 60 frames, cpu)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$1 frames=${2:-60} solver=${3:-cpu}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 "$root/scripts/make_flawed_groom.py" "$tmp/flawed.tfx" >/dev/null
for budget in default 64; do
  sets=()
  [ "$budget" = default ] || sets=(--set sim.max_substeps="$budget")
  "$bin" "$tmp/flawed.tfx" --headless --no-render --quiet --solver "$solver" --frames "$frames" \
    ${sets[@]+"${sets[@]}"} --metrics "$tmp/$budget.json" --export-hair "$tmp/$budget.hair" \
    2>"$tmp/$budget.err"
  sed 's/^/  /' "$tmp/$budget.err"
done
# Debian's python3 has matplotlib (scripts/setup.sh installs it); another first on PATH may not.
py=/usr/bin/python3
[ -x "$py" ] || py=python3
"$py" - "$tmp" "$root/docs/charts" "$frames" "$solver" <<'PY'
import csv, json, math, os, struct, sys
tmp, charts, frames, solver = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]

def read(path):
    data = open(path, "rb").read()
    hairs, points, flags = struct.unpack_from("<III", data, 4)
    off = 128
    segs = struct.unpack_from("<%dH" % hairs, data, off)
    off += 2 * hairs
    xyz = struct.unpack_from("<%df" % (3 * points), data, off)
    strands, at = [], 0
    for s in range(hairs):
        n = segs[s] + 1
        strands.append([xyz[3 * i:3 * i + 3] for i in range(at, at + n)])
        at += n
    return strands

print("| budget | ms a frame | steps a frame (asked) | strands at alpha = 1 | max strain | particles in the head |")
print("|---|---|---|---|---|---|")
for budget in ("default", "64"):
    m = json.load(open(os.path.join(tmp, budget + ".json")))
    st, a = m["stiffness"], m["accuracy"]
    name = "default (%d)" % m["substeps"] if budget == "default" else budget
    print("| %s | %.1f | %d (%d) | %d of %d | %.2f %% | %d |" % (
        name, m["ms"]["sim_mean"], m["substeps"], st["substeps_wanted"], st["strands_at_alpha_1"],
        m["strands"], 100 * a["max_strain"], a["head_penetrations"]))

low, high = read(os.path.join(tmp, "default.hair")), read(os.path.join(tmp, "64.hair"))
assert len(low) == len(high)
bins = [(0.004, 0.02), (0.02, 0.05), (0.05, 0.1), (0.1, 0.2), (0.2, 0.31)]
rows = []
for lo, hi in bins:
    d = []
    strands = 0
    for a, b in zip(low, high):
        length = sum(math.dist(a[i], a[i + 1]) for i in range(len(a) - 1))
        if not (lo <= length < hi):
            continue
        strands += 1
        d += [math.dist(p, q) for p, q in zip(a, b)]
    if not d:
        continue
    d.sort()
    rms = math.sqrt(sum(x * x for x in d) / len(d))
    p99 = d[min(len(d) - 1, int(0.99 * len(d)))]
    rows.append((lo, hi, strands, len(d), rms, p99, d[-1]))
print()
print("Points moved by the budget after %d frames (%s solver), by strand length:" % (frames, solver))
print()
print("| strand length | strands | RMS | 99th percentile | largest |")
print("|---|---|---|---|---|")
for lo, hi, n, _, rms, p99, top in rows:
    print("| %g-%g cm | %d | %.2f mm | %.2f mm | %.2f mm |" % (100 * lo, 100 * hi, n, 1e3 * rms, 1e3 * p99, 1e3 * top))
os.makedirs(charts, exist_ok=True)
with open(os.path.join(charts, "step_budget.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["length_from_m", "length_to_m", "strands", "points", "rms_m", "p99_m", "max_m"])
    w.writerows(rows)
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("bench_step_budget: no matplotlib: the chart is not drawn (the CSV is)")
fig, ax = plt.subplots(figsize=(6.4, 3.6))
labels = ["%g-%g" % (100 * r[0], 100 * r[1]) for r in rows]
x = range(len(rows))
ax.bar([i - 0.2 for i in x], [1e3 * r[4] for r in rows], 0.4, label="RMS")
ax.bar([i + 0.2 for i in x], [1e3 * r[5] for r in rows], 0.4, label="99th percentile")
ax.set_xticks(list(x))
ax.set_xticklabels(labels)
ax.set_xlabel("strand length (cm)")
ax.set_ylabel("points moved by the budget (mm)")
ax.set_title("Flawed TressFX groom, %d frames: default budget against the steps it asks" % frames,
             fontsize=9)
ax.legend()
fig.tight_layout()
for ext in ("png", "svg"):
    fig.savefig(os.path.join(charts, "step_budget." + ext), dpi=110)
PY
