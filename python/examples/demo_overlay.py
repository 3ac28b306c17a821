#!/usr/bin/env python3
"""The demo's stress-strain overlay (report/index.html's curve plot) from results files.

Usage: demo_overlay.py [RESULTS_FOLDER] [OUTPUT_PNG]
  defaults: results/demo (where `scripts/demo.sh` and `geocomp pair cases/demo.prm` write)
  and RESULTS_FOLDER/stress-strain.png.

Reads each engine's <engine>.h5 with geocomp.read_results (h5py; no engine is run) and
plots tau_max against gamma_max as the report does (docs/metrics.md): the logarithmic box
strain from the stage start, the DEM's interval-mean stresses, main paths as lines and
unloading branches thinner. Both axes are sign-free (tau_max, gamma_max >= 0).
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
import numpy  # noqa: E402

import geocomp  # noqa: E402

LABELS = {"dem": "DEM", "continuum": "FE cube", "material-point": "material point"}


def shear_curve(results, stage):
    """gamma_max of the log strain from the stage start [1] and tau_max of the interval-mean stress [Pa]."""
    first = int(numpy.flatnonzero((results.stage == stage) & (results.branch == 0))[0])
    strain = results.log_strain - results.log_strain[first]
    principal_strain = numpy.linalg.eigvalsh(strain)
    principal_stress = numpy.linalg.eigvalsh(results.stress_mean)
    gamma = principal_strain[:, -1] - principal_strain[:, 0]
    tau = 0.5 * (principal_stress[:, -1] - principal_stress[:, 0])
    return gamma, tau


def plot_engine(axes, results, label):
    stage = int(results.stage.max())
    gamma, tau = shear_curve(results, stage)
    main = (results.stage == stage) & (results.branch == 0)
    line, = axes.plot(100 * gamma[main], tau[main] / 1e6, label=label, linewidth=1.6)
    for branch in results.branches:
        if branch["stage"] != stage:
            continue
        rows = numpy.concatenate(([branch["first_sample"]], numpy.flatnonzero(results.branch == branch["id"])))
        axes.plot(100 * gamma[rows], tau[rows] / 1e6, color=line.get_color(), linewidth=0.8)


def main(argv):
    folder = argv[1] if len(argv) > 1 else "results/demo"
    output = argv[2] if len(argv) > 2 else os.path.join(folder, "stress-strain.png")
    found = [e for e in LABELS if os.path.exists(os.path.join(folder, e + ".h5"))]
    if not found:
        sys.exit(f"demo_overlay: no dem.h5, continuum.h5 or material-point.h5 in {folder}: "
                 "run `geocomp pair cases/demo.prm` first")
    figure, axes = plt.subplots(figsize=(7, 4.5))
    for engine in found:
        plot_engine(axes, geocomp.read_results(os.path.join(folder, engine + ".h5")), LABELS[engine])
    axes.set_xlabel("gamma_max [%] (logarithmic strain from the stage start)")
    axes.set_ylabel("tau_max [MPa]")
    axes.set_title("Isochoric shear: stress-strain overlay")
    axes.grid(alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(output, dpi=120)
    print(f"demo_overlay: {', '.join(found)} -> {output}")


if __name__ == "__main__":
    main(sys.argv)
