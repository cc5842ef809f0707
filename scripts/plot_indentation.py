#!/usr/bin/python3
"""Plots an indentation run: force-depth (with the published forearm
reference band and the depths' discretisation error where the run
reports one), the deformed surface profile along y = 0, and the section
y = 0 in the deformed configuration (vertical displacement and von Mises
stress at the last load step, with layer interfaces, septa and punch).

    /usr/bin/python3 scripts/plot_indentation.py output/forearm_indentation

Writes force_depth.png, surface_profile.png and section.png into the run
folder.
"""
import csv, json, os, sys, textwrap

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import run_manifest  # noqa: E402 (scripts/)

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
    label = (f"ssc ({summary['contact']}, "
             f"k = {summary['stiffness_N_per_mm']:.4f} N/mm)")
    reach = depth.max()
    if "depth_uncertainty_mm" in summary:
        # the bar is the size of the error the run computed
        # (depth_uncertainty_method says how); the open marker is where the
        # estimate puts the converged depth
        error = np.array(summary["depth_uncertainty_mm"], dtype=float)
        reach = np.nanmax(depth + error)
        how = summary["depth_uncertainty_method"]
        ax.errorbar(depth, force, xerr=error, fmt="o-", capsize=3,
                    label=label + ";\n" + textwrap.fill(
                        "bars: discretisation error, computed by the run: "
                        + how, 60))
        converged = depth + np.array(summary["depth_error_estimate_mm"],
                                     dtype=float)
        ax.plot(converged, force, "o", mfc="none", color="tab:blue",
                label="the converged depth by that estimate")
    else:
        ax.plot(depth, force, "o-", label=label)
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
    ax.set_xlim(0, reach * 1.05)
    ax.set_ylim(0, force.max() * 1.05)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")
    edge = summary.get("edge_contact", {}).get("edge_radius_mm")
    ax.set_title(f"{summary['run']}: rigid flat punch, radius "
                 f"{summary['punch_radius_mm']} mm" +
                 (f", edge rounded at {edge} mm" if edge else ""),
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(run_manifest.record(run, "force_depth.png"), dpi=110)

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
        fig.savefig(run_manifest.record(run, "surface_profile.png"),
                    dpi=110)

    # section y = 0, in the deformed configuration
    section = os.path.join(run, "section.csv")
    if os.path.exists(section):
        plot_section(run, summary, force[-1], depth[-1])


def plot_section(run, summary, force, depth):
    """The section y = 0 at the last load: every sample point moved by its
    displacement (finite strain: the current configuration; linear: the
    small-strain displacement drawn at scale 1 all the same, so that an
    impossible depth shows), coloured by u_z and von Mises stress, with the
    deformed layer interfaces, the septa's traces and the punch."""
    header, rows = read_csv(os.path.join(run, "section.csv"))
    v = rows.astype(float)
    col = {name: header.index(name) for name in header}
    x, z = v[:, col["x_mm"]], v[:, col["z_mm"]]
    nx = len(np.unique(x))
    shape = (nx, len(x) // nx)
    X = (x + v[:, col["ux_mm"]]).reshape(shape)
    Z = (z + v[:, col["uz_mm"]]).reshape(shape)
    uz = v[:, col["uz_mm"]].reshape(shape)
    layer = v[:, col["layer"]].reshape(shape)
    mises = np.maximum(v[:, col["von_mises_kPa"]].reshape(shape), 1e-6)
    septa_file = os.path.join(run, "section_septa.csv")
    septa = None
    if os.path.exists(septa_file):
        h, r = read_csv(septa_file)
        if len(r):
            s = r.astype(float)
            c = {name: h.index(name) for name in h}
            septa = (np.stack([s[:, c["x0_mm"]] + s[:, c["ux0_mm"]],
                               s[:, c["x1_mm"]] + s[:, c["ux1_mm"]]]),
                     np.stack([s[:, c["z0_mm"]] + s[:, c["uz0_mm"]],
                               s[:, c["z1_mm"]] + s[:, c["uz1_mm"]]]))
    radius = summary.get("punch_radius_mm", None)
    fig, ax = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True)
    panels = [(ax[0], uz, "viridis", "u_z [mm]"),
              (ax[1], np.log10(mises), "magma", "log10 von Mises [kPa]")]
    for a, field, cmap, label in panels:
        m = a.pcolormesh(X, Z, field, cmap=cmap, shading="gouraud")
        fig.colorbar(m, ax=a, label=label)
        a.contour(X, Z, layer, levels=np.arange(0.5, layer.max()),
                  colors="w", linewidths=0.8)
        if septa is not None:
            a.plot(septa[0], septa[1], "-", color="c", lw=0.5, alpha=0.8)
        if radius is not None:
            a.plot(*punch_outline(summary, radius, depth), "r-", lw=2)
        a.set_ylabel("z [mm]")
        a.set_aspect("equal")
    ax[1].set_xlabel("x [mm]")
    ax[0].set_title(f"section y = 0 at {force:g} N, deformed (white: layer "
                    "interfaces, cyan: septa, red: punch)", fontsize=9)
    fig.tight_layout()
    fig.savefig(run_manifest.record(run, "section.png"), dpi=110)


def punch_outline(summary, radius, depth):
    """The punch's section at the given depth: its flat face, the rounded
    edge where the run has one in contact, and its wall up to z = 2 mm."""
    rho = summary.get("edge_contact", {}).get("edge_radius_mm", 0.)
    angle = np.linspace(0, np.pi / 2, 12)
    edge_x = radius - rho + rho * np.sin(angle)
    edge_z = -depth + rho - rho * np.cos(angle)
    x = np.concatenate([[-radius, -radius], -edge_x[::-1], edge_x,
                        [radius, radius]])
    z = np.concatenate([[2., -depth + rho], edge_z[::-1], edge_z,
                        [-depth + rho, 2.]])
    return x, z


if __name__ == "__main__":
    main()
