#!/usr/bin/env bash
# The followers against the same groom with every strand simulated: the default preset at STRANDS
# strands (default 20,000), FRAMES frames (default 60) of its nodding motion, the GPU solver, no
# drawing, collision.mode MODE (default head). Every strand simulated once, then 1 %, 5 % and 20 %
# of them simulated as guides by each variant. For each, at the last frame (every strand exported
# as drawn, the guides found by their roots in an --export-guides of the rest groom), against the
# same points simulated: the guides' own points' RMS, the followers' RMS, 99th percentile and
# largest distance; the points the followers put inside the head (moved out) and the deepest left
# inside. In head mode each strand moves as it would alone and the guides' own points match to
# the bit, so the followers' columns measure the interpolation alone; with the volume or strand
# contacts the guides' own motion depends on what they stand for (METHOD.md 5.1).
# A table, and a chart and CSV into OUT (docs/charts/followers_fidelity[_MODE].png, .csv).
#   scripts/bench_fidelity.sh [BIN] [STRANDS] [FRAMES] [OUT]
# SETS: settings for every run ("collision.friction=0.2 ..."). VARIANTS: the guided runs, each
# LABEL=BINARY[,SETTING=VALUE...] (e.g. "before=/tmp/old after=build/app/csmhair
# wisps=build/app/csmhair,collision.wisps=true"); default "this=BIN". Every strand simulated
# runs with BIN.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$root/build/app/csmhair"}
strands=${2:-20000}
frames=${3:-60}
out=${4:-"$root/docs/charts"}
mode=${MODE:-head}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run=(--headless --no-render --solver gpu --set hairstyle.strands="$strands"
     --set collision.mode="$mode")
for set in ${SETS:-}; do run+=(--set "$set"); done
variants=(${VARIANTS:-"this=$bin"})
echo "Load before: $(uptime | sed 's/.*load average: //')"
"$bin" "${run[@]}" --quiet --frames "$frames" --set hairstyle.guides=0 --export-hair "$tmp/all.hair"
"$bin" "${run[@]}" --quiet --frames 0 --set hairstyle.guides=0 --export-hair "$tmp/rest.hair"
shares="1 5 20"
labels=()
for variant in "${variants[@]}"; do
  label=${variant%%=*}
  IFS=, read -r -a parts <<<"${variant#*=}"
  vbin=${parts[0]}
  vsets=()
  for set in "${parts[@]:1}"; do vsets+=(--set "$set"); done
  labels+=("$label")
  for share in $shares; do
    guides=$((strands * share / 100))
    "$vbin" "${run[@]}" ${vsets[@]+"${vsets[@]}"} --frames "$frames" --set hairstyle.guides=$guides \
      --export-hair "$tmp/$label.g$share.hair" 2>"$tmp/$label.g$share.log" >/dev/null
    "$vbin" "${run[@]}" --quiet --frames 0 --set hairstyle.guides=$guides --export-guides \
      --export-hair "$tmp/$label.g$share.rest.hair"
  done
done
echo "Load after: $(uptime | sed 's/.*load average: //')"
/usr/bin/python3 - "$tmp" "$out" "$strands" "$frames" "$mode" "$shares" "$root/scripts" "${labels[@]}" <<'PY'
import re, sys
import numpy as np
sys.path.insert(0, sys.argv[7])
from hair_file import read
tmp, out, strands, frames, mode = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
shares = [int(s) for s in sys.argv[6].split()]
labels = sys.argv[8:]

all_x, first = read(f"{tmp}/all.hair")
rest_x, rest_first = read(f"{tmp}/rest.hair")
roots = rest_x[rest_first[:-1]]
rows = []
for label, share in [(l, s) for l in labels for s in shares]:
    x, f = read(f"{tmp}/{label}.g{share}.hair")
    assert len(f) == len(first) and np.array_equal(f, first), "the drawn groom is not the groom"
    gx, gf = read(f"{tmp}/{label}.g{share}.rest.hair")
    guide_roots = gx[gf[:-1]]
    # The guides: the strands whose rest roots are the guides' roots.
    is_guide = np.zeros(len(roots), bool)
    key = {tuple(np.round(r, 5)): i for i, r in enumerate(roots)}
    for r in guide_roots:
        is_guide[key[tuple(np.round(r, 5))]] = True
    follower_points = np.concatenate([np.arange(first[s], first[s + 1])
                                      for s in range(len(roots)) if not is_guide[s]])
    d = np.linalg.norm(x[follower_points] - all_x[follower_points], axis=1) * 1e3
    guide_points = np.concatenate([np.arange(first[s], first[s + 1])
                                   for s in range(len(roots)) if is_guide[s]])
    dg = np.linalg.norm(x[guide_points] - all_x[guide_points], axis=1) * 1e3
    log = open(f"{tmp}/{label}.g{share}.log").read()
    m = re.search(r"the followers: (\d+) points moved out of the head, the deepest left inside ([0-9.]+) mm", log)
    pushed, deepest = (int(m.group(1)), float(m.group(2))) if m else (-1, -1.0)
    rows.append((label, share, int(is_guide.sum()), len(follower_points), np.sqrt(np.mean(d * d)),
                 np.percentile(d, 99), d.max(), pushed, deepest, np.sqrt(np.mean(dg * dg))))
print()
print(f"{strands:,} strands, {frames} frames of the nodding motion, collision.mode={mode}; the "
      "points through guides against the same points simulated")
print()
print("| variant | guides | share | follower points | RMS mm | 99th percentile mm | largest mm | guides' own RMS mm | points moved out of the head | deepest left inside mm |")
print("|---|---|---|---|---|---|---|---|---|---|")
for label, share, g, n, rms, p99, mx, pushed, deepest, grms in rows:
    print(f"| {label} | {g:,} | {share} % | {n:,} | {rms:.2f} | {p99:.2f} | {mx:.1f} | {grms:.3f} | {pushed:,} | {deepest:.3f} |")
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
fig, ax = plt.subplots(figsize=(6, 3.6))
for label in labels:
    mine = [r for r in rows if r[0] == label]
    xs = [r[1] for r in mine]
    tag = f"{label}: " if len(labels) > 1 else ""
    ax.plot(xs, [r[4] for r in mine], "o-", label=f"{tag}followers' RMS")
    ax.plot(xs, [r[5] for r in mine], "s--", label=f"{tag}99th percentile")
    if mode != "head":
        ax.plot(xs, [r[9] for r in mine], "^:", label=f"{tag}guides' own RMS")
ax.set_xscale("log")
ax.set_xticks(shares)
ax.set_xticklabels([f"{s} %" for s in shares])
ax.set_xlabel("strands simulated (guides)")
ax.set_ylabel("point error (mm)")
ax.set_ylim(bottom=0)
ax.set_title(f"Through guides against every strand simulated\n({strands:,} strands, {frames} frames, "
             f"collision.mode={mode})", fontsize=10)
ax.grid(True, alpha=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
name = "followers_fidelity" + ("" if mode == "head" else "_" + mode.replace("+", "_"))
fig.savefig(f"{out}/{name}.png", dpi=110)
with open(f"{out}/{name}.csv", "w") as c:
    c.write("variant,share_percent,guides,follower_points,rms_mm,p99_mm,max_mm,pushed_points,deepest_inside_mm,guides_rms_mm\n")
    for r in rows:
        c.write(",".join(f"{v:.4f}" if isinstance(v, float) else str(v) for v in r) + "\n")
PY
