#!/usr/bin/python3
"""Pictures of an incision run (Run/Scene = incision): for each of the two
cuts, the skin surface around the wound at full pre-tension, coloured by
the skin's stress across the cut (the tension the cut released: low at the
lips, raised at the cut's ends), the planned cut (dashed) and the opened
lips; below, the gap against the pre-tension as it comes on. For an
excision (Incision/Shape = disc) one panel: the von Mises stress, the
planned disc and the wound's rim; below, the wound's area change. For an
ellipse excised along x and along y, one panel each: the planned ellipse,
the opened wound's rim and, where sutures closed it (Incision/Closure), the
skin's von Mises stress in the closed state with the sutures' stations;
below, the force per suture as the closure proceeds (or the area change).

    /usr/bin/python3 scripts/plot_incision.py RUN_DIR [HALF_WIDTH_MM]

writes RUN_DIR/incision.png.
"""
import glob, json, os, sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_manifest  # noqa: E402 (scripts/)
import vtu  # noqa: E402


def skin_surface(folder, step):
    """Top faces of the skin's top cells, deformed, and their stresses."""
    faces, values = [], {"stress_xx": [], "stress_yy": [], "von_mises": []}
    # one file per rank
    for piece in sorted(glob.glob(os.path.join(folder,
                                               f"volume_{step:04d}.*.vtu"))):
        mesh = vtu.read(piece)
        points = mesh["points"] + mesh["point_data"]["displacement"]
        reference = mesh["points"]
        layer = vtu.cell_values(mesh, "layer").round().astype(int)
        for k, cell in enumerate(vtu.cells(mesh)):
            if layer[k] != 0 or len(cell) != 8:
                continue
            top = cell[4:]  # VTK hexahedron: bottom face, then top face
            if reference[top, 2].min() < -1e-9:
                continue
            faces.append(points[top, :2])
            for name in values:
                values[name].append(vtu.cell_values(mesh, name)[k])
    return faces, {n: np.array(v) for n, v in values.items()}


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    folder = sys.argv[1]
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    wound = summary["wound"]
    lips = np.genfromtxt(os.path.join(folder, "wound_lips.csv"),
                         delimiter=",", names=True, dtype=None,
                         encoding="utf-8")
    table = np.genfromtxt(os.path.join(folder, "wound.csv"), delimiter=",",
                          names=True, dtype=None, encoding="utf-8")
    disc = "excision" in wound or "planned_diameter_mm" in wound
    ellipse = "ellipse_along_x" in wound
    closure = summary.get("closure")
    if disc:
        panels = [(1, "disc", wound)]
        length = wound["planned_diameter_mm"]
    elif ellipse:
        panels = [(1, "x", wound["ellipse_along_x"]),
                  (2, "y", wound["ellipse_along_y"])]
        length = wound["ellipse_along_x"]["planned_length_mm"]
    else:
        panels = [(1, "x", wound["cut_along_x"]), (2, "y", wound["cut_along_y"])]
        length = wound["cut_along_x"]["planned_length_mm"]
    half = float(sys.argv[2]) if len(sys.argv) > 2 else 1.2 * length

    fig = plt.figure(figsize=(10 if not disc else 6.5, 8.4),
                     constrained_layout=True)
    grid = fig.add_gridspec(2, len(panels), height_ratios=[3, 1.3])
    for step, name, entry in panels:
        ax = fig.add_subplot(grid[0, step - 1])
        faces, stress = skin_surface(folder, step)
        if disc or ellipse:
            # deviatoric: Q1-P0's mean stress shows its pressure checkerboard
            shown = stress["von_mises"] * 1e3
            label = "skin von Mises stress (kPa)" + (
                ", closed" if closure else "")
        else:
            shown = stress["stress_yy" if name == "x" else "stress_xx"] * 1e3
            label = "skin stress across the cut (kPa)"
        if faces:
            collection = PolyCollection(faces, array=shown, cmap="viridis",
                                        edgecolors="face", linewidths=0.2)
            ax.add_collection(collection)
            fig.colorbar(collection, ax=ax, shrink=0.8, label=label)
        if disc:
            angle = np.linspace(0, 2 * np.pi, 200)
            plan = length / 2 * np.stack([np.cos(angle), np.sin(angle)], 1)
        elif ellipse:
            angle = np.linspace(0, 2 * np.pi, 200)
            semi = [length / 2, entry["planned_width_mm"] / 2]
            if name == "y":
                semi = semi[::-1]
            plan = np.stack([semi[0] * np.cos(angle),
                             semi[1] * np.sin(angle)], 1)
        else:
            plan = np.array([[-length / 2, 0], [length / 2, 0]])
            if name == "y":
                plan = plan[:, ::-1]
        ax.plot(plan[:, 0], plan[:, 1], "k--", lw=1,
                label="planned " + ("disc" if disc else "ellipse"
                                    if ellipse else "cut"))
        if ellipse:
            rim = lips[lips["cut"] == name]
            order = np.argsort(rim["t"])
            ax.plot(np.append(rim["x"][order], rim["x"][order][0]),
                    np.append(rim["y"][order], rim["y"][order][0]), "r-",
                    lw=1.2, label="opened wound")
            where = entry.get("relative_to_langer_lines")
            title = (f"ellipse along {name}" +
                     (f" ({where} Langer's lines)" if where else "") +
                     f": opened {entry['area_change_pct']:+.3g} % area")
            if closure:
                closed = closure[f"ellipse_along_{name}"]
                stations = np.array(closed["suture_stations_mm"])
                points = np.stack([stations, 0 * stations], 1)
                if name == "y":
                    points = points[:, ::-1]
                ax.plot(points[:, 0], points[:, 1], "wx", ms=6, mew=1.5,
                        label="sutures (closed)")
                title += (f"\nclosed: {closed['force_per_suture_N']:.3g} N "
                          f"per suture, dog ears "
                          f"{closed['dog_ear_height_mm']:.2g} mm,\nskin "
                          f"stress up to {closed['max_skin_stress_kPa']:.3g}"
                          " kPa")
        elif disc:
            rim = lips[lips["cut"] == "disc"]
            order = np.argsort(rim["t"])
            ax.plot(np.append(rim["x"][order], rim["x"][order][0]),
                    np.append(rim["y"][order], rim["y"][order][0]), "r-",
                    lw=1.5, label="wound")
            title = (f"excision: area {entry['area_change_pct']:+.3g} %, "
                     f"aspect ratio {entry['aspect_ratio']:.3g}, long axis "
                     f"{entry['orientation_deg']:.3g} deg\nfreed disc "
                     f"{summary['disc']['area_change_pct']:+.3g} %")
        else:
            for side in (-1, 1):
                mine = lips[(lips["cut"] == name) & (lips["side"] == side)]
                ax.plot(mine["x"], mine["y"], "r-", lw=1.5,
                        label="lips" if side == 1 else None)
            where = entry.get("relative_to_langer_lines")
            title = (f"cut along {name}" +
                     (f" ({where} Langer's lines)" if where else "") +
                     f"\ngap {entry['gap_mm']:.3g} mm, area "
                     f"{entry['area_mm2']:.3g} mm$^2$, length/gap "
                     f"{entry['aspect_ratio']:.3g}")
        ax.set_title(title, fontsize=9)
        ax.set_xlim(-half, half)
        ax.set_ylim(-half, half)
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
        ax.legend(loc="lower right", fontsize=8)
    ax = fig.add_subplot(grid[1, :])
    if closure:
        steps = np.genfromtxt(os.path.join(folder, "closure.csv"),
                              delimiter=",", names=True, dtype=None,
                              encoding="utf-8")
    for _, name, entry in panels:
        rows = table[table["cut"] == name]
        if closure:
            mine = steps[steps["cut"] == name]
            where = entry.get("relative_to_langer_lines")
            ax.plot(np.append(0, 100 * mine["closure_fraction"]),
                    np.append(0, mine["force_per_suture_N"]),
                    "o-" if name == "x" else "s--",
                    label=f"ellipse along {name}" +
                    (f" ({where} Langer's lines)" if where else ""))
        elif ellipse:
            ax.plot(100 * rows["prestretch_fraction"],
                    100 * (rows["area_mm2"] / entry["planned_area_mm2"] - 1),
                    "o-" if name == "x" else "s--",
                    label=f"ellipse along {name}")
        elif disc:
            planned = wound["planned_area_mm2"]
            ax.plot(100 * rows["prestretch_fraction"],
                    100 * (rows["area_mm2"] / planned - 1), "o-",
                    label="wound")
        else:
            ax.plot(100 * rows["prestretch_fraction"], rows["gap_mm"],
                    "o-" if name == "x" else "s--", label=f"cut along {name}")
    tension = wound["skin_tension_N_per_m"]
    if closure:
        ax.set_xlabel("closure (% of the lips' distance drawn together; "
                      f"skin tension {tension['x']:.3g} / {tension['y']:.3g} "
                      "N/m along x / y)")
        ax.set_ylabel("force per suture (N)")
    else:
        ax.set_xlabel("pre-tension applied (% of the prestretch; full: "
                      f"{tension['x']:.3g} / {tension['y']:.3g} N/m along "
                      "x / y)")
        ax.set_ylabel("wound area change (%)" if disc or ellipse else
                      "gap (mm)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    kind = ("closure of an elliptic excision" if closure else "excision"
            if disc or ellipse else "incision")
    fig.suptitle(f"{summary['run']}: {kind} of the pre-tensioned skin")
    fig.savefig(run_manifest.record(folder, "incision.png"), dpi=130)


if __name__ == "__main__":
    main()
