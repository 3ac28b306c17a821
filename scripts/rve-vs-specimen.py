#!/usr/bin/python3
"""Tables and plot data of the RVE against the wall-bounded specimen (scripts/rve-vs-specimen.sh).

Usage: rve-vs-specimen.py <output dir>

Reads every <family>-n<N>-s<seed>.csv that geocomp-bench-rve-vs-specimen wrote in the folder
(and in its rate2/ and damping0/ checks), and writes
  <dir>/summary.md    the state before shear, the figures of every run, each family's mean,
                      SD and range, the band check, and the checks against their base runs;
  <dir>/plot/*.dat    the curves on a common grid of axial strain (window means, as the runs'
                      own figures: coupled/wall/CurveMetrics.h), one file per run and per family.
Signs as in the runs: axial strain compression positive, volumetric strain tension positive
(contraction < 0); q/p with p the current mean pressure.
"""
import glob
import os
import sys

import numpy as np

WINDOW = 0.005                              # as CurveMetrics: 0.5 % of axial strain
GRID = np.arange(0.005, 0.10 + 1e-9, 0.001)  # where the band check looks
LABELS = {"rve": "RVE", "wall": "wall", "cell": "cell of the wall specimen"}


def read_run(path):
    run = {"path": path, "sections": {}}
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                words = line[1:].split()
                if words[0] == "family":
                    run["family"] = words[1]
                    continue
                run["sections"][words[0]] = {k: float(v) if _number(v) else v
                                             for k, v in (w.split("=", 1) for w in words[1:])}
            elif line[0].isdigit() or line[0] == "-":
                rows.append([float(x) for x in line.split(",")])
    run["curve"] = np.array(rows)
    run["particles"] = int(run["sections"]["run"]["particles"])
    run["seed"] = int(run["sections"]["run"]["seed"])
    return run


def _number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def window_curve(curve, column):
    """Window means of one column on GRID (the last window kept inside the curve)."""
    e, v = curve[:, 0], curve[:, column]
    end = e[-1]
    out = []
    for g in GRID:
        lo, hi = min(g - WINDOW / 2, end - WINDOW), min(g + WINDOW / 2, end)
        sel = (e >= lo) & (e <= hi)
        out.append(v[sel].mean() if g <= end + 1e-9 and sel.any() else np.nan)
    return np.array(out)


ORDER = {"rve": 0, "wall": 1, "cell": 2}


def families(runs):
    """Runs by (family, particles): the RVEs, the wall specimens, their cells; smaller first."""
    out = {}
    for r in runs:
        out.setdefault((r["family"], r["particles"]), []).append(r)
    for key in out:
        out[key].sort(key=lambda r: r["seed"])
    return dict(sorted(out.items(), key=lambda kv: (kv[0][1] == 1000 and kv[0][0] == "wall" or kv[0][1] == 4000,
                                                    ORDER[kv[0][0]], kv[0][1])))


def label(key):
    return f"{LABELS[key[0]]} {key[1]}"


def stats(values):
    v = np.array(values, dtype=float)
    sd = v.std(ddof=1) if len(v) > 1 else 0.0
    return v.mean(), sd, v.min(), v.max()


METRICS = [("peak q/p", "metrics", "peak_stress_ratio", 1, 3),
           ("at e_a", "metrics", "peak_strain", 100, 1),
           ("q/p 2 %", "metrics", "stress_ratio_2", 1, 3),
           ("q/p 5 %", "metrics", "stress_ratio_5", 1, 3),
           ("q/p 10 %", "metrics", "stress_ratio_10", 1, 3),
           ("e_v 5 % [%]", "metrics", "volumetric_5", 100, 2),
           ("e_v 10 % [%]", "metrics", "volumetric_10", 100, 2)]
STATE = [("phi", "state", "packing_fraction", 1, 4),
         ("phi inner", "state", "inner_packing_fraction", 1, 4),
         ("Z", "state", "coordination", 1, 2),
         ("Z inner", "state", "inner_coordination", 1, 2),
         ("inner N", "state", "inner_particles", 1, 0),
         ("d [mm]", "state", "mean_diameter", 1000, 3),
         ("edge [d]", "state", "edge_diameters", 1, 1),
         ("I", "metrics", "mean_inertial_number", 1e4, 2),
         ("lateral error [%]", "metrics", "largest_lateral_error", 100, 2)]


def value(run, spec):
    _, section, key, scale, _ = spec
    return run["sections"][section][key] * scale


def fmt(x, digits):
    return f"{x:.{digits}f}"


def per_run_table(fams, specs):
    head = "| family | seed | " + " | ".join(s[0] for s in specs) + " |"
    lines = [head, "|" + "---|" * (len(specs) + 2)]
    for key, runs in fams.items():
        for r in runs:
            lines.append(f"| {label(key)} | {r['seed']} | " +
                         " | ".join(fmt(value(r, s), s[4]) for s in specs) + " |")
    return "\n".join(lines)


def family_table(fams, specs):
    head = "| family (seeds) | " + " | ".join(s[0] for s in specs) + " |"
    lines = [head, "|" + "---|" * (len(specs) + 1)]
    for key, runs in fams.items():
        cells = []
        for s in specs:
            m, sd, lo, hi = stats([value(r, s) for r in runs])
            d = s[4]
            cells.append(f"{fmt(m, d)} ± {fmt(sd, d)} [{fmt(lo, d)}, {fmt(hi, d)}]")
        lines.append(f"| {label(key)} ({len(runs)}) | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def band(fams, column):
    """Per family: the mean curve, the SD and the min-max envelope on GRID."""
    out = {}
    for key, runs in fams.items():
        c = np.array([window_curve(r["curve"], column) for r in runs])
        out[key] = (np.nanmean(c, axis=0), np.nanstd(c, axis=0, ddof=1) if len(runs) > 1 else 0 * c[0],
                    np.nanmin(c, axis=0), np.nanmax(c, axis=0))
    return out


def band_table(fams, pairs):
    lines = ["| mean curve of | inside the band of | q/p in min-max | q/p in mean ± SD | e_v in min-max | e_v in mean ± SD |",
             "|---|---|---|---|---|---|"]
    ratio, volume = band(fams, 2), band(fams, 1)
    for a, b in pairs:
        if a not in fams or b not in fams:
            continue
        cells = []
        for bands in (ratio, volume):
            mean_a = bands[a][0]
            mb, sdb, lob, hib = bands[b]
            ok = ~np.isnan(mean_a) & ~np.isnan(mb)
            inside = (mean_a >= lob) & (mean_a <= hib)
            inside_sd = np.abs(mean_a - mb) <= sdb
            cells += [f"{100 * inside[ok].mean():.0f} %", f"{100 * inside_sd[ok].mean():.0f} %"]
        lines.append(f"| {label(a)} | {label(b)} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def outside(mean_a, band_b):
    """The strain intervals [%] where mean_a leaves band_b's min-max envelope."""
    _, _, lo, hi = band_b
    out, start = [], None
    for g, m, l, h in zip(100 * GRID, mean_a, lo, hi):
        bad = not (np.isnan(m) or np.isnan(l)) and not (l <= m <= h)
        if bad and start is None:
            start = g
        if not bad and start is not None:
            out.append(f"{start:.1f}-{previous:.1f}")
            start = None
        previous = g
    if start is not None:
        out.append(f"{start:.1f}-{previous:.1f}")
    return ", ".join(out) if out else "none"


def outside_table(fams, pairs):
    lines = ["| mean curve of | outside the min-max band of | q/p: at e_a [%] | e_v: at e_a [%] |", "|---|---|---|---|"]
    ratio, volume = band(fams, 2), band(fams, 1)
    for a, b in pairs:
        if a in fams and b in fams:
            lines.append(f"| {label(a)} | {label(b)} | {outside(ratio[a][0], ratio[b])} | {outside(volume[a][0], volume[b])} |")
    return "\n".join(lines)


def difference_table(fams, pairs):
    """Difference of the family means and its standard error sqrt(s_a^2/n_a + s_b^2/n_b)."""
    specs = [METRICS[0]] + METRICS[2:]
    lines = ["| A - B | " + " | ".join(s[0] for s in specs) + " |", "|" + "---|" * (len(specs) + 1)]
    for a, b in pairs:
        if a not in fams or b not in fams:
            continue
        cells = []
        for spec in specs:
            ma, sa, _, _ = stats([value(r, spec) for r in fams[a]])
            mb, sb, _, _ = stats([value(r, spec) for r in fams[b]])
            se = np.sqrt(sa ** 2 / len(fams[a]) + sb ** 2 / len(fams[b]))
            d = spec[4]
            cells.append(f"{ma - mb:+.{d}f} ({(ma - mb) / se:+.1f} SE)" if se > 0 else f"{ma - mb:+.{d}f}")
        lines.append(f"| {label(a)} - {label(b)} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def checks_table(checks, base):
    lines = ["| check | family | seed | peak q/p (base) | q/p 5 % (base) | q/p 10 % (base) | e_v 10 % [%] (base) | I (base) |",
             "|---|---|---|---|---|---|---|---|"]
    index = {(r["family"], r["particles"], r["seed"]): r for r in base}
    for name, runs in checks:
        for r in runs:
            b = index.get((r["family"], r["particles"], r["seed"]))
            if b is None:
                continue
            cells = []
            for s in (METRICS[0], METRICS[3], METRICS[4], METRICS[6], STATE[7]):
                d = s[4]
                cells.append(f"{fmt(value(r, s), d)} ({fmt(value(b, s), d)})")
            lines.append(f"| {name} | {LABELS[r['family']]} {r['particles']} | {r['seed']} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def write_plot_data(directory, fams):
    os.makedirs(directory, exist_ok=True)
    ratio, volume = band(fams, 2), band(fams, 1)
    for key, runs in fams.items():
        name = f"{key[0]}-n{key[1]}"
        rows = np.column_stack([100 * GRID, *ratio[key], *(100 * x for x in volume[key])])
        np.savetxt(os.path.join(directory, name + ".dat"), rows, fmt="%.6g",
                   header="e_a[%] q/p: mean sd min max; e_v[%]: mean sd min max")
        for r in runs:
            rows = np.column_stack([100 * GRID, window_curve(r["curve"], 2), 100 * window_curve(r["curve"], 1)])
            np.savetxt(os.path.join(directory, f"{name}-s{r['seed']}.dat"), rows, fmt="%.6g",
                       header="e_a[%] q/p e_v[%]")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = sys.argv[1]
    base = [read_run(p) for p in sorted(glob.glob(os.path.join(root, "*.csv")))]
    if not base:
        sys.exit(f"no runs in {root}")
    fams = families(base)
    checks = [(name, [read_run(p) for p in sorted(glob.glob(os.path.join(root, name, "*.csv")))])
              for name in ("rate2", "damping0")]
    pairs = [(("rve", 500), ("wall", 5000)), (("wall", 5000), ("rve", 500)),
             (("cell", 5000), ("wall", 5000)), (("wall", 5000), ("cell", 5000)),
             (("rve", 500), ("cell", 5000)), (("cell", 5000), ("rve", 500)),
             (("rve", 4000), ("rve", 500)), (("wall", 1000), ("wall", 5000))]
    text = ["# The RVE against the wall-bounded specimen: runs in " + root, "",
            "Axial strain compression positive, volumetric strain tension positive (contraction < 0);",
            "q/p with p the current mean pressure; every figure a mean over 0.5 % of axial strain.", "",
            "## State before shear (mean ± SD [min, max]; I x 1e4 is the shear's mean inertial number)", "",
            family_table(fams, STATE), "",
            "## Figures, each family", "", family_table(fams, METRICS), "",
            "## Band check: where a family's mean curve lies in another's scatter (0.5 to 10 %)", "",
            band_table(fams, pairs), "", outside_table(fams, pairs), "",
            "## Differences of the family means (and in standard errors of the difference)", "",
            difference_table(fams, [(("rve", 500), ("wall", 5000)), (("cell", 5000), ("wall", 5000)),
                                    (("rve", 4000), ("rve", 500)), (("cell", 5000), ("rve", 4000)),
                                    (("wall", 1000), ("wall", 5000))]), "",
            "## Checks against their base runs (rate2: 2 /s; damping0: no local damping while shearing)", "",
            checks_table(checks, base), "",
            "## Every run", "", per_run_table(fams, STATE[:4] + METRICS), ""]
    with open(os.path.join(root, "summary.md"), "w") as f:
        f.write("\n".join(text))
    write_plot_data(os.path.join(root, "plot"), fams)
    print(os.path.join(root, "summary.md"))


if __name__ == "__main__":
    main()
