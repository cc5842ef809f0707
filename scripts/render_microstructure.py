#!/usr/bin/python3
"""Renders the septa and skin ligaments of a geometry run to PNG: a 3D view
and a vertical section through y = 0.

    /usr/bin/python3 scripts/render_microstructure.py output/forearm_geometry \
        [--window 24] [--out FILE.png]

Reads septa.vtu and ligaments.vtu from the run folder and draws the central
window x, y in [-w/2, w/2] (mm): septa of the SAT (RCS) in orange, of the
DAT (RCP) in blue, ligaments in black; the section shows where the septa
cut the plane y = 0 and the ligaments within 1 mm of it. Writes microstructure.png into
the run folder unless --out is given.
"""
import argparse, json, os, sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection, Line3DCollection

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_manifest  # noqa: E402
import vtu  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run")
    parser.add_argument("--window", type=float, default=24.0)
    parser.add_argument("--out")
    parser.add_argument("--dpi", type=int, default=110)
    args = parser.parse_args()
    half = args.window / 2

    septa = vtu.read(os.path.join(args.run, "septa.vtu"))
    ligaments = vtu.read(os.path.join(args.run, "ligaments.vtu"))
    with open(os.path.join(args.run, "summary.json")) as f:
        summary = json.load(f)

    fig = plt.figure(figsize=(13, 6))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    section = fig.add_subplot(1, 2, 2)
    light = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    colour = {0: (0.95, 0.55, 0.15), 1: (0.2, 0.45, 0.85)}
    z_min = 0.0
    if "points" in septa and len(vtu.cells(septa)):
        triangles = septa["points"][np.stack(vtu.cells(septa))]
        tag = vtu.cell_values(septa, "tag_RCS0_RCP1").round().astype(int)
        z_min = triangles[:, :, 2].min()
        # section y = 0: the segment where each triangle crosses the plane
        for t, g in zip(triangles, tag):
            y = t[:, 1]
            if y.min() > 0 or y.max() < 0 or \
                    np.abs(t[:, 0]).min() > half:
                continue
            cuts = []
            for a, b in ((0, 1), (1, 2), (2, 0)):
                if (y[a] <= 0) != (y[b] <= 0):
                    s_ = y[a] / (y[a] - y[b])
                    cuts.append(t[a] + s_ * (t[b] - t[a]))
            if len(cuts) == 2:
                section.plot([cuts[0][0], cuts[1][0]],
                             [cuts[0][2], cuts[1][2]], color=colour[g],
                             linewidth=1.2)
        centres = triangles.mean(axis=1)
        keep = (np.abs(centres[:, 0]) <= half) & (np.abs(centres[:, 1]) <= half)
        triangles, tag = triangles[keep], tag[keep]
        normals = np.cross(triangles[:, 1] - triangles[:, 0],
                           triangles[:, 2] - triangles[:, 0])
        normals /= np.linalg.norm(normals, axis=1)[:, None] + 1e-300
        shade = 0.45 + 0.55 * np.abs(normals @ light)
        base = np.array([colour[g] for g in tag])
        colours = np.clip(base * shade[:, None], 0, 1)
        ax.add_collection3d(Poly3DCollection(triangles, facecolors=colours,
                                             edgecolors="none", alpha=0.55))
    if "points" in ligaments and len(vtu.cells(ligaments)):
        segments = ligaments["points"][np.stack(vtu.cells(ligaments))]
        mid = segments.mean(axis=1)
        keep = (np.abs(mid[:, 0]) <= half) & (np.abs(mid[:, 1]) <= half)
        ax.add_collection3d(Line3DCollection(segments[keep], colors="k",
                                             linewidths=1.6))
        near = keep & (np.abs(mid[:, 1]) <= 1.0)
        for s_ in segments[near]:
            section.plot(s_[:, 0], s_[:, 2], color="k", linewidth=1.6)
        if keep.any():
            z_min = min(z_min, segments[keep][:, :, 2].min())
    section.set_xlim(-half, half)
    section.set_ylim(z_min - 0.5, 0.5)
    section.axhline(0, color="0.5", linewidth=0.8)
    section.set_aspect("equal")
    section.set_xlabel("x [mm]")
    section.set_ylabel("z [mm]")
    section.set_title("section y = 0 (skin surface at z = 0)", fontsize=9)
    ax.set_xlim(-half, half)
    ax.set_ylim(-half, half)
    ax.set_zlim(z_min, 0)
    ax.set_box_aspect((1, 1, max(0.25, -z_min / args.window)))
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_zlabel("z [mm]")
    ax.view_init(elev=22, azim=-60)
    layers = summary.get("microstructure", {}).get("layers", [])
    text = ", ".join(f"{l['layer']}: {l['lobules']} lobules" for l in layers)
    ax.set_title(f"{summary['run']}: septa (orange RCS, blue RCP), "
                 f"{summary.get('ligament_count', 0)} ligaments (black)\n"
                 f"{text}; central {args.window:g} mm shown", fontsize=9)
    out = args.out or run_manifest.record(args.run, "microstructure.png")
    fig.tight_layout()
    fig.savefig(out, dpi=args.dpi)
    print(out)


if __name__ == "__main__":
    main()
