#!/usr/bin/python3
"""Plots an indentation run: force-depth (with the published forearm
reference band), the surface profile u_z(x) along y = 0, and the section
y = 0 (vertical displacement and von Mises stress at the last load step).

    /usr/bin/python3 scripts/plot_indentation.py output/forearm_indentation

Writes force_depth.png, surface_profile.png and section.png into the run
folder.
"""
import csv, json, os, sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REFERENCE = os.path.join(ROOT, "prm", "reference",
                         "forearm_stiffness_flynn2011.csv")


def read_csv(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f
                                      if not line.startswith("#"))]
    return rows[0], np.array(rows[1:], dtype=object)


def main():
    run = sys.argv[1]
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)
    force = np.array(summary["force_N"], dtype=float)
    depth = np.array(summary["depth_mm"], dtype=float)

    # force-depth
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(depth, force, "o-", label=f"ssc ({summary['contact']}, "
            f"k = {summary['stiffness_N_per_mm']:.4f} N/mm)")
    if os.path.exists(REFERENCE):
        header, rows = read_csv(REFERENCE)
        for r in rows:
            k_min = float(r[header.index("stiffness_min_N_per_mm")])
            k_max = float(r[header.index("stiffness_max_N_per_mm")])
            f = np.linspace(0, max(force.max(), 1.8), 50)
            ax.fill_betweenx(f, f / k_max, f / k_min, alpha=0.25,
                             color="tab:green",
                             label=f"{r[0]}: {k_min}-{k_max} N/mm "
                                   "(force/displacement, other device)")
    ax.set_xlabel("depth [mm]")
    ax.set_ylabel("force [N]")
    ax.set_xlim(0, depth.max() * 1.05)
    ax.set_ylim(0, force.max() * 1.05)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")
    ax.set_title(f"{summary['run']}: rigid flat punch, radius "
                 f"{summary['punch_radius_mm']} mm", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "force_depth.png"), dpi=110)

    # surface profile
    profile = os.path.join(run, "surface_profile.csv")
    if os.path.exists(profile):
        header, rows = read_csv(profile)
        values = rows.astype(float)
        fig, ax = plt.subplots(figsize=(7, 4))
        for j in range(1, len(header)):
            ax.plot(values[:, 0], values[:, j],
                    label=header[j].replace("uz_mm_at_", ""))
        ax.axvspan(-summary["punch_radius_mm"], summary["punch_radius_mm"],
                   color="0.85", label="punch")
        ax.set_xlabel("x [mm] (y = 0)")
        ax.set_ylabel("surface displacement u_z [mm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
        ax.set_title("surface profile through the punch centre", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(run, "surface_profile.png"), dpi=110)

    # section y = 0
    section = os.path.join(run, "section.csv")
    if os.path.exists(section):
        header, rows = read_csv(section)
        v = rows.astype(float)
        x, z = v[:, 0], v[:, 1]
        nx = len(np.unique(x))
        shape = (nx, len(x) // nx)
        X, Z = x.reshape(shape), z.reshape(shape)
        fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
        c0 = ax[0].contourf(X, Z, v[:, 4].reshape(shape), 30, cmap="viridis")
        fig.colorbar(c0, ax=ax[0], label="u_z [mm]")
        mises = np.maximum(v[:, 5].reshape(shape), 1e-6)
        c1 = ax[1].contourf(X, Z, np.log10(mises), 30, cmap="magma")
        fig.colorbar(c1, ax=ax[1], label="log10 von Mises [kPa]")
        layer = v[:, 2].reshape(shape)
        for a in ax:
            a.contour(X, Z, layer, levels=np.arange(0.5, layer.max()),
                      colors="w", linewidths=0.6)
            a.set_ylabel("z [mm]")
            a.set_aspect("equal")
        ax[1].set_xlabel("x [mm]")
        ax[0].set_title(f"section y = 0 at {force[-1]} N (reference "
                        "configuration; white: layer interfaces)", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(run, "section.png"), dpi=110)


if __name__ == "__main__":
    main()
