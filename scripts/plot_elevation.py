#!/usr/bin/python3
"""Maps of the skin elevation of growth runs side by side, top view, with
one colour scale for all runs: the elevation u_z (top row) and what is left
of it after removing the smooth trend (bottom row, the orange peel and the
dimples), with each run's metrics from its summary.json.

    /usr/bin/python3 scripts/plot_elevation.py OUT.png RUN_DIR[=TITLE] ...

e.g.
    /usr/bin/python3 scripts/plot_elevation.py output/cheek_injection.png \\
        output/cheek_injection_dat="DAT" output/cheek_injection_sat="SAT"
"""
import json, os, sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_run(folder):
    data = np.genfromtxt(os.path.join(folder, "elevation.csv"),
                         delimiter=",", names=True)
    x, y = np.unique(data["x_mm"]), np.unique(data["y_mm"])
    shape = (len(y), len(x))  # x runs fastest
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    return (x, y, data["uz_mm"].reshape(shape),
            data["residual_mm"].reshape(shape), summary)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], []
    for arg in sys.argv[2:]:
        folder, _, title = arg.partition("=")
        runs.append((title or os.path.basename(folder.rstrip("/")),
                     read_run(folder)))
    top = max(np.abs(r[2]).max() for _, r in runs)
    detail = max(np.abs(r[3]).max() for _, r in runs)
    fig, axes = plt.subplots(2, len(runs), figsize=(4.2 * len(runs), 8.6),
                             squeeze=False, constrained_layout=True)
    for k, (title, (x, y, uz, residual, summary)) in enumerate(runs):
        extent = [x[0], x[-1], y[0], y[-1]]
        surface = summary["surface"]
        image = axes[0, k].imshow(uz, origin="lower", extent=extent,
                                  cmap="viridis", vmin=min(0, -top), vmax=top)
        axes[0, k].set_title(
            f"{title}\nmax {summary['max_elevation_mm']:.3g} mm, "
            f"mean {summary['mean_elevation_mm']:.3g} mm", fontsize=9)
        detail_image = axes[1, k].imshow(residual, origin="lower",
                                         extent=extent, cmap="RdBu_r",
                                         vmin=-detail, vmax=detail)
        axes[1, k].set_title(
            f"Sa {surface['Sa_mm']:.3g}, Sq {surface['Sq_mm']:.3g}, "
            f"Svm {surface['Svm_mm']:.3g}, Sz {surface['Sz_mm']:.3g} mm,\n"
            f"{surface['dimples']['count']} dimples", fontsize=9)
        for row in range(2):
            axes[row, k].set_xlabel("x (mm)")
            axes[row, k].set_ylabel("y (mm)")
    fig.colorbar(image, ax=axes[0, :], label="skin elevation u_z (mm)")
    fig.colorbar(detail_image, ax=axes[1, :],
                 label="elevation minus trend (mm)")
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
