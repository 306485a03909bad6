#!/usr/bin/python3
"""Charts for docs/BENCHMARKS.md ("Speed against accuracy") from the CSV csmhair-bench and the
bench scripts write.

usage: /usr/bin/python3 scripts/charts.py DIR [SECTION...]

Reads DIR/{methods,stability,resolution,region_sums,scaling,scene_choices,window_coefficient,
window_sag,modes,contact_settings,torture,soak_rss,scale}.csv (whichever are there; with SECTIONs,
only those sections': methods, stability, ..., window, modes, contact_settings, torture, soak)
and writes PNG and SVG charts next to them. Needs only Debian's python3-matplotlib.
"""
import csv
import json
import math
import os
import sys

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

plt.rcParams.update({
    "figure.dpi": 110,
    "font.size": 9,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "svg.hashsalt": "csmhair",  # stable SVG ids, so regenerated files diff cleanly
})

FAMILY_STYLE = {
    "CSM": ("#1f77b4", "o"),
    "CSM calibrated": ("#2ca02c", "o"),
    "GPU CSM calibrated": ("#006400", "*"),
    "CSM calibrated (steps capped)": ("#2ca02c", "o"),
    "CSM calibrated + DFTL 0.9 (steps capped)": ("#2ca02c", "^"),
    "CSM, no strain limit": ("#17becf", "v"),
    "CSM + DFTL 0.9": ("#bcbd22", "^"),
    "CSM, hair-hair collisions": ("#9467bd", "P"),
    "GPU CSM": ("#000000", "*"),
    "MS explicit": ("#d62728", "s"),
    "MS implicit": ("#ff7f0e", "D"),
    "MS implicit, stiff": ("#8c564b", "d"),
    "PBD": ("#e377c2", "X"),
    "FTL (DFTL 0.9)": ("#7f7f7f", "h"),
}


def style(family):
    return FAMILY_STYLE.get(family, ("#bcbd22", "o"))


def read(path):
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(row, key):
    v = row.get(key, "")
    if v in ("", None):
        return math.nan
    try:
        return float(v)
    except ValueError:
        return math.nan


def save(fig, out, name, rect=None):
    """Lays out (within `rect` of the figure, when given: room for a legend or title) and
    writes out/name.png and out/name.svg."""
    fig.tight_layout(rect=rect)
    for ext in ("png", "svg"):
        path = os.path.join(out, f"{name}.{ext}")
        fig.savefig(path, metadata={"Date": None} if ext == "svg" else None)
    plt.close(fig)
    print(f"charts.py: {name}.png, {name}.svg")


def families(rows):
    seen = []
    for r in rows:
        if r["family"] not in seen:
            seen.append(r["family"])
    return seen


# ---- cost against error --------------------------------------------------------------------

MEASURES = [
    # key, file name, axis label, transform, log x
    ("max_strain", "cost_vs_stretch", "largest segment stretch over the run (0.05 = 5%)",
     lambda v: v, True),
    ("timestep_rms_mm", "cost_vs_timestep_error",
     "time-step error: RMS distance to the same scene with 16x substeps (mm)", lambda v: v, True),
    ("resolution_rms_mm", "cost_vs_resolution_error",
     "resolution error: tip path of 8 and 16 particles vs 32, RMS over 1 s of swing (mm)",
     lambda v: v, True),
    ("pendulum_error_pct", "cost_vs_pendulum_error",
     "pendulum: |period error| of a rigid strand against 2 pi sqrt(2L/3g) (%)", abs, True),
    ("hair_pairs_closer_than_r", "cost_vs_hair_penetration",
     "hair-hair penetration: segment pairs closer than the hair radius (mean of samples)",
     lambda v: v, False),
]


def cost_charts(rows, out, scene_note):
    for key, name, label, transform, logx in MEASURES:
        fig, ax = plt.subplots(figsize=(7.5, 5.0))
        finite_x = [transform(num(r, key)) for r in rows
                    if r["diverged"] != "1" and math.isfinite(num(r, key))]
        floor = min([x for x in finite_x if x > 0], default=1e-3) / 3 if logx else 0.0
        right = max(finite_x, default=1.0)
        for fam in families(rows):
            colour, marker = style(fam)
            groups = {}  # one line per setting that differs only in substeps
            for r in rows:
                if r["family"] != fam:
                    continue
                y = num(r, "ms_per_sim_s")
                x = transform(num(r, key))
                if r["diverged"] == "1" or not math.isfinite(x):
                    # Blew up: drawn at the right edge with a cross.
                    xb = right * (3 if logx else 1.1)
                    ax.scatter([xb], [y], marker="x", color=colour, s=40)
                    ax.annotate(r["label"] + " (blew up)", (xb, y), fontsize=6, color=colour,
                                xytext=(3, 2), textcoords="offset points")
                    continue
                if logx and x <= 0:
                    x = floor
                group = r["label"].rsplit(" s", 1)[0] if " s" in r["label"] else ""
                groups.setdefault(group, []).append((x, y, r["label"]))
            first = True
            for pts in groups.values():
                pts.sort(key=lambda p: p[1])
                ax.plot([p[0] for p in pts], [p[1] for p in pts], color=colour, marker=marker,
                        linestyle="-", linewidth=0.7, markersize=5,
                        label=fam if first else None)
                first = False
                for x, y, lab in pts:
                    ax.annotate(lab, (x, y), fontsize=5.5, color=colour, xytext=(3, 2),
                                textcoords="offset points")
            if first:
                ax.scatter([], [], color=colour, marker=marker, label=fam + " (all blew up)")
        if logx:
            ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(label + ("  (x = blew up)" if any(r["diverged"] == "1" for r in rows)
                               else ""))
        ax.set_ylabel("cost: ms per simulated second (CPU, one thread)")
        ax.set_title(f"Cost against error — {scene_note}", fontsize=9)
        ax.legend(fontsize=7, loc="best")
        save(fig, out, name)


# ---- stability maps --------------------------------------------------------------------------

CATEGORIES = ["stable", "energy gain", "energy", "stretch", "nan"]
CAT_COLOURS = ["#b7e4b0", "#fff2a8", "#fdae61", "#e34a33", "#7f0000"]
CAT_LABELS = ["stable", "bounded, energy gain > 10%", "blew up: energy > 1.5x",
              "blew up: stretch > 100%", "blew up: NaN"]


def stability_chart(rows, out):
    fams = families(rows)
    cols = 4 if len(fams) > 6 else 3
    nrows = math.ceil(len(fams) / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(4.1 * cols, 3.4 * nrows + 0.6),
                             squeeze=False)
    cmap = ListedColormap(CAT_COLOURS)
    for idx, fam in enumerate(fams):
        ax = axes[idx // cols][idx % cols]
        fr = [r for r in rows if r["family"] == fam]
        subs = sorted({int(num(r, "substeps")) for r in fr})
        stiff = sorted({num(r, "stiffness") for r in fr})
        grid = [[0] * len(subs) for _ in stiff]
        for r in fr:
            i = stiff.index(num(r, "stiffness"))
            j = subs.index(int(num(r, "substeps")))
            cat = r["blowup"]
            if cat == "stable" and num(r, "energy_ratio") > 1.1:
                cat = "energy gain"
            grid[i][j] = CATEGORIES.index(cat)
            text = ""
            if r["blowup"] == "stable":
                ms = num(r, "max_strain")
                text = f"{100 * ms:.0f}%" if ms >= 0.01 else ""
                if num(r, "energy_ratio") > 1.1:
                    text = f"{num(r, 'energy_ratio'):.1f}x"
            ax.text(j, i, text, ha="center", va="center", fontsize=5.5)
        ax.imshow(grid, cmap=cmap, vmin=-0.5, vmax=len(CATEGORIES) - 0.5, origin="lower",
                  aspect="auto")
        ax.set_xticks(range(len(subs)))
        ax.set_xticklabels([f"1/{60 * s}" for s in subs], rotation=45, fontsize=6)
        ax.set_yticks(range(len(stiff)))
        ax.set_yticklabels([f"{v:g}" for v in stiff], fontsize=7)
        ax.set_xlabel("time step h (s)")
        ax.set_ylabel(fr[0]["stiffness_name"], fontsize=7)
        ax.set_title(fam, fontsize=9)
        ax.grid(False)
    for idx in range(len(fams), nrows * cols):
        axes[idx // cols][idx % cols].axis("off")
    handles = [plt.Rectangle((0, 0), 1, 1, color=c) for c in CAT_COLOURS]
    fig.legend(handles, CAT_LABELS, loc="lower center", ncol=5, fontsize=7, frameon=False)
    fig.suptitle("Stability: four 25 cm strands released horizontally, 2 s; cell text = largest "
                 "stretch (or energy gain)", fontsize=9)
    save(fig, out, "stability", rect=(0, 0.05, 1, 0.96))


# ---- the rest ----------------------------------------------------------------------------------


def scaling_chart(rows, out):
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    series = []
    for r in rows:
        if r["series"] not in series:
            series.append(r["series"])
    for s in series:
        pts = [(num(r, "strands"), num(r, "ms_per_step"), num(r, "particles")) for r in rows
               if r["series"] == s]
        dashed = "hair-hair" in s
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o",
                linestyle="--" if dashed else "-", label=s)
        last = pts[-1]
        ax.annotate(f"{last[1]:.0f} ms", (last[0], last[1]), fontsize=7, xytext=(4, 0),
                    textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("strands (default preset's hairstyle, 8-16 particles each)")
    ax.set_ylabel("ms per step (1 substep per frame)")
    ax.axhline(1000 / 60, color="k", linewidth=0.6, linestyle=":")
    ax.annotate("60 fps", (ax.get_xlim()[0], 1000 / 60), fontsize=7, xytext=(2, 2),
                textcoords="offset points")
    ax.set_title("Scaling: ms per step against strand count", fontsize=9)
    ax.legend(fontsize=7)
    save(fig, out, "scaling")


def scale_chart(rows, out):
    """scripts/bench_scale.sh: start-up, memory, sim and render ms against the strands drawn."""
    fig, axes = plt.subplots(2, 2, figsize=(8, 6))
    panels = (("startup_s", "start-up s", None),
              ("peak_rss_mb", "peak RSS MB (solid), solver buffers MB (dotted)",
               "solver_buffers_mb"),
              ("sim_ms", "sim ms a frame", None),
              ("render_ms", "render ms a frame (followers pass dotted)", "followers_ms"))
    colours = {"default": "#2ca02c", "all": "#d62728"}
    labels = {"default": "default guides (all up to 20,000, 4,000 beyond)",
              "all": "every strand simulated"}
    for ax, (key, title, dotted) in zip(axes.flat, panels):
        for series in ("default", "all"):
            pts = [r for r in rows if r["guides"] == series]
            xs = [num(r, "strands") for r in pts]
            ax.plot(xs, [num(r, key) for r in pts], marker="o", color=colours[series],
                    label=labels[series])
            if dotted:  # a pass a series has not (0) is left out of the log axis
                some = [(x, num(r, dotted)) for x, r in zip(xs, pts) if num(r, dotted) > 0]
                ax.plot([p[0] for p in some], [p[1] for p in some], marker=".", linestyle=":",
                        color=colours[series])
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("strands drawn (32 points each)")
    axes.flat[0].legend(fontsize=7)
    fig.suptitle(f"What a groom costs as it grows: {rows[0].get('device', '?')}", fontsize=9)
    save(fig, out, "scale", rect=(0, 0, 1, 0.96))


def region_chart(rows, out):
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for sums, colour in (("prefix", "#1f77b4"), ("direct", "#d62728")):
        pts = [(num(r, "window"), num(r, "ms_per_step")) for r in rows if r["sums"] == sums]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", color=colour,
                label=f"{sums} sums")
    ax.set_xlabel("stiffness window w (particles)")
    ax.set_ylabel("ms per step")
    ax.set_ylim(bottom=0)
    r0 = rows[0]
    ax.set_title(f"Region sums: prefix differences against direct sums "
                 f"({int(num(r0, 'strands'))} strands x 32 particles)", fontsize=9)
    ax.legend(fontsize=8)
    save(fig, out, "region_sums")


def resolution_chart(rows, out):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.2))
    lines = []
    for r in rows:
        key = (r["family"], r["label"])
        if key not in lines:
            lines.append(key)
    for fam, lab in lines:
        pts = [(num(r, "particles"), num(r, "sag_mm"), num(r, "swing_tip_rms_vs_finest_mm"),
                r["window"]) for r in rows if r["family"] == fam and r["label"] == lab]
        colour, marker = style(fam)
        ls = "-"
        if fam == "CSM":
            colour = {"w = 2 particles": "#1f77b4", "w = 4 particles": "#aec7e8"}.get(
                lab, "#2ca02c" if "3.3" in lab else "#98df8a")
            ls = "--" if "cm" in lab else "-"
        elif fam == "CSM calibrated":
            colour = "#54278f" if lab.startswith("2 cm") else "#000000"
            ls = "-"
        name = f"{fam}: {lab}"
        a1.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker, color=colour,
                linestyle=ls, label=name)
        a2.plot([p[0] for p in pts[:-1]], [p[2] for p in pts[:-1]], marker=marker,
                color=colour, linestyle=ls, label=name)
        if fam == "CSM":
            for p in pts:
                a1.annotate(f"w{p[3]}", (p[0], p[1]), fontsize=6, color=colour,
                            xytext=(3, -8), textcoords="offset points")
    for a in (a1, a2):
        a.set_xlabel("particles per strand")
        a.set_xticks(sorted({num(r, "particles") for r in rows}))
    a1.set_ylabel("sag of the tip (mm), settled, gravity 1 m/s^2")
    a1.set_title("Stiffness against resolution: sag of a 12 cm cantilever", fontsize=9)
    a2.set_ylabel("tip path RMS against the finest (mm)")
    a2.set_title("Swing: 1 s after release, g = 9.81, against 32 particles", fontsize=9)
    a1.legend(fontsize=6)
    save(fig, out, "resolution")


def scene_chart(rows, out):
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    groups = [("particles", "centreline RMS vs 32 particles (mm)"),
              ("substeps", "position RMS vs 32 substeps (mm)")]
    for ax, (g, xlabel) in zip((axes[0], axes[2]), groups):
        gr = [r for r in rows if r["group"] == g]
        for r in gr:
            x, y = num(r, "error_rms_mm"), num(r, "ms_per_frame")
            ax.scatter([x], [y], color="#1f77b4")
            ax.annotate(f"{r['variant']} ({int(num(r, 'particles'))} p)", (x, y), fontsize=6,
                        xytext=(3, 2), textcoords="offset points")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("ms per frame (CPU)")
        ax.set_title(g, fontsize=9)
    ax = axes[1]
    gr = [r for r in rows if r["group"] == "collisions"]
    names = [r["variant"] for r in gr]
    ms = [num(r, "ms_per_frame") for r in gr]
    bars = ax.bar(names, ms, color="#1f77b4")
    for b, r in zip(bars, gr):
        ax.annotate(f"{num(r, 'head_penetrations'):.0f} particles in head\n"
                    f"{num(r, 'hair_pairs_closer_than_r'):.0f} hair pairs < r\n"
                    f"({num(r, 'hair_pairs_at_start'):.0f} at start)",
                    (b.get_x() + b.get_width() / 2, b.get_height()), ha="center", fontsize=6,
                    xytext=(0, 2), textcoords="offset points")
    ax.set_ylabel("ms per frame (CPU)")
    ax.set_title("collisions: cost, and penetrations left", fontsize=9)
    ax.margins(y=0.25)
    s = rows[0]
    fig.suptitle(f"Model no more than a scene needs: presets/default.json, "
                 f"{int(num(s, 'strands'))} strands", fontsize=9)
    save(fig, out, "scene_choices")


def window_chart(coefficients, sags, out):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.0))
    if coefficients:
        w = [num(r, "w") for r in coefficients]
        a1.plot(w, [num(r, "measured") for r in coefficients], marker="o", markersize=3,
                label="measured on the CPU solver")
        a1.plot(w, [num(r, "table") for r in coefficients], linestyle="--", color="k",
                linewidth=0.8, label="table (w <= 16), (1 + 2/w) / 45 beyond")
        a1.axhline(1 / 45, color="#999999", linewidth=0.6, linestyle=":")
        a1.annotate("1/45", (w[-1], 1 / 45), fontsize=7, xytext=(-20, -10),
                    textcoords="offset points")
        a1.set_xlabel("w: particles per side of a region")
        a1.set_ylabel("c_w: mu = c_w (kappa w l)^4")
        a1.set_title("The window coefficient the calibration uses", fontsize=9)
        a1.legend(fontsize=7)
    if sags:
        for g, ls in ((1.0, "-"), (9.81, "--")):
            for n, colour in ((16, "#1f77b4"), (32, "#ff7f0e"), (64, "#2ca02c")):
                pts = [(100 * num(r, "window_length_m"), num(r, "sag_mm")) for r in sags
                       if num(r, "gravity") == g and num(r, "particles") == n]
                a2.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", markersize=3,
                        color=colour, linestyle=ls, label=f"{n} particles, g = {g:g}")
            beam = [num(r, "beam_sag_mm") for r in sags if num(r, "gravity") == g]
            if beam and g == 1.0:
                a2.axhline(beam[0], color="k", linewidth=0.7, linestyle=":")
                a2.annotate("Euler-Bernoulli beam, g = 1", (1, beam[0]), fontsize=7,
                            xytext=(2, 3), textcoords="offset points")
        a2.set_yscale("log")
        a2.set_xlabel("window length (cm), bending stiffness fixed")
        a2.set_ylabel("sag of a 12 cm clamped strand (mm)")
        a2.set_title("What the window still does at a fixed bending stiffness", fontsize=9)
        a2.legend(fontsize=6)
    save(fig, out, "window")


MODE_STYLE = {"off": ("#7f7f7f", "v"), "head": ("#1f77b4", "o"), "strands": ("#9467bd", "P"),
              "volume": ("#2ca02c", "s"), "volume+strands": ("#d62728", "D"),
              "strands:4": ("#e377c2", "X"), "strands@penalty": ("#bcbd22", "^"),
              "volume+strands@penalty": ("#ff7f0e", "<")}


def mode_label(mode):
    """A bench_modes.sh mode as the legend says it: MODE:N is MODE with N contact
    iterations a substep, MODE@MODEL with that contact model (the paper's penalty)."""
    name, _, iterations = mode.partition(":")
    name, _, model = name.partition("@")
    if model:
        name = f"{name}, {model}" + (" (the paper's)" if model == "penalty" else "")
    return f"{name}, {iterations} iterations" if iterations else name


def modes_chart(rows, out):
    """scripts/bench_modes.sh: cost against strand count, and against what hair-hair leaves
    (pairs closer than r per strand, crossings per second), for every collision mode. Where
    the CSV splits the crossings (crossings_close_per_s: pairs the groom put closer than 2r,
    which may cross where they crossed at rest), the solid line is the crossings of pairs that
    were apart and the dotted one all of them. A row of a mode with strand contacts whose
    crossings are empty had candidates over the buffers (those frames kept the list before
    them): its cost is not the mode's, and it is left out."""
    fig, axes = plt.subplots(1, 3, figsize=(12, 4))
    rows = [r for r in rows
            if "strands" not in r["mode"] or (r.get("crossings_per_s") or "") != ""]
    modes = []
    for r in rows:
        if r["mode"] not in modes:
            modes.append(r["mode"])
    for m in modes:
        color, marker = MODE_STYLE.get(m, ("#bcbd22", "o"))
        def apart(r):
            close = r.get("crossings_close_per_s") or ""
            return num(r, "crossings_per_s") - (float(close) if close else 0.0)
        pts = sorted((num(r, "strands"), num(r, "sim_ms"), num(r, "pairs_r"),
                      num(r, "crossings_per_s"), apart(r)) for r in rows if r["mode"] == m)
        split = any(r.get("crossings_close_per_s") for r in rows if r["mode"] == m)
        xs = [p[0] for p in pts]
        axes[0].plot(xs, [p[1] for p in pts], marker=marker, color=color, label=mode_label(m))
        axes[1].plot([p[2] / p[0] for p in pts], [p[1] for p in pts], marker=marker,
                     color=color, label=mode_label(m))
        if split:
            axes[2].plot([max(p[3], 1.0) for p in pts], [p[1] for p in pts], marker=marker,
                         color=color, linestyle=":", alpha=0.5, markerfacecolor="none")
        axes[2].plot([max(p[4], 1.0) for p in pts], [p[1] for p in pts], marker=marker,
                     color=color, label=mode_label(m))
        for p in pts:
            axes[1].annotate(f"{p[0] / 1000:g}k", (p[2] / p[0], p[1]), fontsize=6,
                             xytext=(3, 0), textcoords="offset points")
    axes[0].set_xscale("log")
    axes[0].set_xlabel("strands")
    axes[0].set_title("Cost against strand count", fontsize=9)
    axes[1].set_xlabel("pairs closer than r, per strand (end of run)")
    axes[1].set_title("Cost against penetration", fontsize=9)
    axes[2].set_xscale("log")
    axes[2].set_xlabel("crossings per second (1 where none)\n"
                       "solid: of pairs apart at rest; dotted: all")
    axes[2].set_title("Cost against crossings", fontsize=9)
    for ax in axes:
        ax.set_yscale("log")
        ax.set_ylabel("simulation ms per frame")
        ax.legend(fontsize=7)
    save(fig, out, "modes")


def contact_settings_chart(rows, out):
    """scripts/bench_contact_settings.sh: `strands` mode's contact settings (iterations,
    substeps, margin, lists a frame, the solve) at one strand count, their cost a frame against the
    penetration depth's median and 99th percentile and the crossings of pairs apart at rest;
    head only and twice it as lines (the issue's cost target). A row whose lists did not fit
    (crossings empty) is left out. Runs that list more than once a frame count crossings
    between lists that much closer in time, so they see more of them: their crossings are
    not comparable with the others' (the legend says so)."""
    from matplotlib.lines import Line2D
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.5))
    head = [num(r, "sim_ms") for r in rows if r["mode"] == "head"]
    runs = [r for r in rows if r["mode"] != "head" and (r.get("crossings_per_s") or "") != ""]
    colours = {"1": "#1f77b4", "2": "#2ca02c", "4": "#d62728", "8": "#9467bd",
               "16": "#ff7f0e"}
    markers = {"1": "D", "2": "v", "4": "p", "5": "o", "8": "s", "16": "^"}
    for r in runs:
        close = r.get("crossings_close_per_s") or ""
        apart = num(r, "crossings_per_s") - (float(close) if close else 0.0)
        colour = colours.get(r["lists"], "#7f7f7f")
        marker = markers.get(r["substeps"], "o")
        face = "none" if r.get("margin_mm") else colour
        alpha = 0.4 if r.get("solve") == "jacobi" else 1.0
        for ax, x in ((axes[0], num(r, "depth_p50")), (axes[1], num(r, "depth_p99")),
                      (axes[2], max(apart, 1.0))):
            ax.plot([x], [num(r, "sim_ms")], marker=marker, color=colour, markerfacecolor=face,
                    linestyle="none", alpha=alpha)
            ax.annotate(r["setting"], (x, num(r, "sim_ms")), fontsize=6, xytext=(3, 2),
                        textcoords="offset points")
    for ax in axes:
        if head:
            ax.axhline(head[0], color="#555555", linewidth=0.8)
            ax.axhline(2 * head[0], color="#555555", linewidth=0.8, linestyle="--")
            ax.annotate("head only", (0.01, head[0]), xycoords=("axes fraction", "data"),
                        fontsize=7, xytext=(0, 2), textcoords="offset points")
            ax.annotate("2x head only", (0.01, 2 * head[0]), xycoords=("axes fraction", "data"),
                        fontsize=7, xytext=(0, 2), textcoords="offset points")
        ax.set_yscale("log")
        ax.yaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
        ax.yaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
        ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_ylabel("simulation ms per frame")
    axes[1].axvline(0.25, color="#2ca02c", linewidth=0.8, linestyle=":")
    axes[0].set_xlabel("penetration depth p50 (r)")
    axes[1].set_xlabel("penetration depth p99 (r); dotted: the target, 0.25 r")
    axes[2].set_xscale("log")
    axes[2].set_xlabel("crossings per second of pairs apart at rest")
    n = runs[0]["strands"] if runs else "?"
    axes[0].set_title(f"Cost against median depth ({n} strands)", fontsize=9)
    axes[1].set_title("Cost against p99 depth", fontsize=9)
    axes[2].set_title("Cost against crossings", fontsize=9)
    legend = []
    for k, c in colours.items():
        if any(r["lists"] == k for r in runs):
            label = "1 list a frame" if k == "1" else (
                f"{k} lists a frame (crossings counted {k}x as often)")
            legend.append(Line2D([], [], color=c, marker="o", linestyle="none", label=label))
    legend += [Line2D([], [], color="#555555", marker=m, linestyle="none", label=f"{k} substeps")
               for k, m in markers.items() if any(r["substeps"] == k for r in runs)]
    if any(r.get("margin_mm") for r in runs):
        legend.append(Line2D([], [], color="#555555", marker="o", markerfacecolor="none",
                             linestyle="none", label="margin changed (hollow)"))
    if any(r.get("solve") == "jacobi" for r in runs):
        legend.append(Line2D([], [], color="#555555", marker="o", alpha=0.4, linestyle="none",
                             label="collision.solve = jacobi (faded)"))
    axes[2].legend(handles=legend, fontsize=7, loc="lower right")
    save(fig, out, "contact_settings")



# ---- reliability: the torture map and the soak (docs/RELIABILITY.md) --------------------------

TORTURE_COLOURS = ["#b7e4b0", "#fdae61", "#e34a33", "#7f0000", "#ffffff"]
TORTURE_LABELS = ["pass", "fails one criterion", "fails two or more", "non-finite",
                  "not run"]


def torture_note(r):
    """The worst measure of a cell, short: what failed, else the stretch and peak speed."""
    if r["finite"] != "1":
        return f"NaN f{r['nonfinite_frame']}"
    parts = []
    if r["stretch_ok"] != "1":
        parts.append(f"S{100 * num(r, 'max_strain'):.0f}%")
    if r["head_ok"] != "1":
        parts.append(f"H{num(r, 'deepest_mm'):.1f}mm")
    if r["speed_ok"] != "1":
        parts.append(f"V{num(r, 'peak_speed'):.0f}/{num(r, 'speed_bound'):.0f}")
    if not parts:
        return f"{num(r, 'peak_speed'):.1f}"
    return "\n".join(parts)


def torture_chart(rows, out):
    """csmhair-bench --only torture: every cell (axis = value, rows) in every collision mode and
    solver (columns), coloured by the criteria it fails."""
    cells, columns = [], []
    for r in rows:
        key = (r["axis"], r["value"])
        if key not in cells:
            cells.append(key)
        col = (r["solver"], r["mode"])
        if col not in columns:
            columns.append(col)
    grid = [[4] * len(columns) for _ in cells]
    fig, ax = plt.subplots(figsize=(1.05 * len(columns) + 3.2, 0.3 * len(cells) + 1.6))
    for r in rows:
        i, j = cells.index((r["axis"], r["value"])), columns.index((r["solver"], r["mode"]))
        failed = sum(r[k] != "1" for k in ("stretch_ok", "head_ok", "speed_ok"))
        grid[i][j] = 3 if r["finite"] != "1" else min(failed, 2)
        ax.text(j, i, torture_note(r), ha="center", va="center", fontsize=5.2,
                color="white" if grid[i][j] == 3 else "black")
    ax.imshow(grid, cmap=ListedColormap(TORTURE_COLOURS), vmin=-0.5,
              vmax=len(TORTURE_COLOURS) - 0.5, aspect="auto")
    ax.set_xticks(range(len(columns)))
    ax.set_xticklabels([f"{s.upper()}\n{m}" for s, m in columns], fontsize=6.5)
    ax.xaxis.tick_top()
    ax.set_yticks(range(len(cells)))
    ax.set_yticklabels([f"{a}: {v}" for a, v in cells], fontsize=6.5)
    for i in range(1, len(cells)):
        if cells[i][0] != cells[i - 1][0]:
            ax.axhline(i - 0.5, color="black", linewidth=0.6)
    for j in range(1, len(columns)):
        if columns[j][0] != columns[j - 1][0]:
            ax.axvline(j - 0.5, color="black", linewidth=1.2)
    ax.grid(False)
    handles = [plt.Rectangle((0, 0), 1, 1, color=c, ec="#999999") for c in TORTURE_COLOURS]
    fig.legend(handles, TORTURE_LABELS, loc="lower center", ncol=5, fontsize=7, frameon=False)
    strands = int(num(rows[0], "strands"))
    fig.suptitle(f"Torture map: the default preset, {strands} strands, one factor at a time; "
                 "text: S = largest stretch, H = deepest inside the head, V = peak speed / "
                 "bound (m/s); a passing cell shows its peak speed", fontsize=8)
    save(fig, out, "torture", rect=(0, 0.03, 1, 0.97))


def soak_chart(rows, out):
    """csmhair-bench --only soak: the resident set over the run, per solver."""
    summary = {r["solver"]: r for r in (read(os.path.join(out, "soak.csv")) or [])}
    fig, ax = plt.subplots(figsize=(6.5, 3.2))
    for solver in sorted({r["solver"] for r in rows}):
        pts = [(num(r, "frame"), num(r, "rss_kb") / 1024) for r in rows if r["solver"] == solver]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=".", label=solver.upper())
        if solver in summary:
            ax.axvline(num(summary[solver], "moving_frames"), color="#999999", linestyle=":")
    ax.set_xlabel("frame (dotted: the head stops)")
    ax.set_ylabel("resident set (MiB)")
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=7)
    ax.set_title("Soak: memory over the run", fontsize=9)
    save(fig, out, "soak")


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = sys.argv[1]
    # Sections named after DIR: only their charts (csmhair-bench --only passes them).
    only = set(sys.argv[2:])

    def wanted(name):
        return not only or name in only

    meta = {}
    if os.path.exists(os.path.join(out, "meta.json")):
        with open(os.path.join(out, "meta.json")) as f:
            meta = json.load(f)
    methods = read(os.path.join(out, "methods.csv")) if wanted("methods") else None
    if methods:
        note = (f"{int(num(methods[0], 'strands'))} strands, "
                f"{int(num(methods[0], 'particles'))} particles, nodding head")
        cost_charts(methods, out, note)
    for name, section, fn in (("stability", "stability", stability_chart),
                              ("scaling", "scaling", scaling_chart),
                              ("scale", "scale", scale_chart),
                              ("region_sums", "region_sums", region_chart),
                              ("resolution", "resolution", resolution_chart),
                              ("scene_choices", "scene_choices", scene_chart),
                              ("modes", "modes", modes_chart),
                              ("contact_settings", "contact_settings", contact_settings_chart),
                              ("torture", "torture", torture_chart),
                              ("soak_rss", "soak", soak_chart)):
        rows = read(os.path.join(out, f"{name}.csv")) if wanted(section) else None
        if rows:
            fn(rows, out)
    if wanted("window"):
        coefficients = read(os.path.join(out, "window_coefficient.csv"))
        sags = read(os.path.join(out, "window_sag.csv"))
        if coefficients or sags:
            window_chart(coefficients, sags, out)
    if meta:
        print(f"charts.py: from {meta.get('command', '?')} on {meta.get('cores', '?')} cores, "
              f"{meta.get('cpu', '?')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
