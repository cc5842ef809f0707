#!/usr/bin/python3
"""Discretisation error of the in vivo probe model (prm/probe_indentation.prm)
against CalculiX: which mesh and degree the identification's forward model
needs for 1 % and what it costs.

The problem (the same as calculix_probe.py in this folder, which computes
the reference with 20-node bricks converged by its own level sequence): the
MULTIS forearm trial of prm/probe_indentation.prm (skin 1.655, fat 3.823,
muscle 16.832 mm over rigid bone) with skin E = 0.05, fat and muscle
E = 0.02 MPa, one nu, linear elasticity, a 105 x 68 mm patch with fixed
sides and base, the 45 x 8 mm probe bonded and pressed 1 mm. Compared: the
stiffness K = F / d and each layer's strain under the probe centre.

ssc runs prm/probe_indentation.prm with linear layers and displacement
control, on box meshes graded towards the probe's edges (Mesh/Core edge
cell size, Grading ratio) with Q1 and Q2 (mixed formulation), on the
quarter x >= 0, y >= 0 (Mesh/Symmetry = quarter: the same answers as the
whole patch, test probe_quarter), one process on one core, the Cholesky
preconditioner. Writes
benchmarks/identification/results/probe_convergence.csv and .png.

    /usr/bin/python3 benchmarks/identification/probe_convergence.py
        [--nu 0.49 0.3] [--plot-only]
"""
import argparse, csv, os, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

ROOT = ssc_runner.ROOT
PRM = os.path.join(ROOT, "prm", "probe_indentation.prm")
OUT = os.path.join(HERE, "results")
LAYERS = ["skin", "fat", "muscle"]
MODULI = {"skin": 0.05, "fat": 0.02, "muscle": 0.02}
FIELDS = ["degree", "cell_size", "edge_size", "grading", "cells_across",
          "nu", "dofs", "K_N_per_mm", "strain_skin", "strain_fat",
          "strain_muscle", "error_K", "error_strain_fat",
          "error_strain_muscle", "wall_s"]

# (degree, Cell size, Core edge cell size, Grading ratio, cells across the
# skin / fat / muscle)
MESHES = [(1, 2, 0.5, 1.4, (1, 2, 4)), (1, 2, 0.25, 1.4, (1, 2, 4)),
          (1, 2, 0.125, 1.4, (1, 2, 4)),
          (2, 8, 2, 2.0, (1, 1, 2)), (2, 8, 1, 2.0, (1, 1, 2)),
          (2, 8, 2, 2.0, (2, 2, 3)), (2, 8, 1, 2.0, (2, 3, 4)),
          (2, 4, 1, 1.8, (1, 1, 2)), (2, 4, 0.5, 1.8, (1, 1, 2)),
          (2, 4, 0.5, 1.8, (2, 3, 4))]


def reference(nu):
    """The finest C3D20R level of calculix_probe.py at this nu."""
    path = os.path.join(OUT, "calculix_probe.csv")
    rows = [r for r in csv.DictReader(open(path))
            if abs(float(r["nu"]) - nu) < 1e-12 and r["element"] == "C3D20R"]
    best = max(rows, key=lambda r: int(r["level"]))
    return {k: float(best[k]) for k in
            ["K_N_per_mm", "strain_skin", "strain_fat", "strain_muscle"]}


def run_ssc(nu, mesh, folder):
    degree, h, edge, grading, across = mesh
    name = f"q{degree}_h{h}_e{edge}_g{grading}_{'-'.join(map(str, across))}_nu{nu}"
    settings = ["Run/Write fields=false",
                "Punch/Section=false", "Punch/Profile length=0",
                "Punch/Control=displacement", "Punch/Depth=1",
                f"Elasticity/Degree={degree}",
                f"Mesh/Cell size={h}", f"Mesh/Grading ratio={grading}",
                f"Mesh/Core edge cell size={edge}",
                "Mesh/Symmetry=quarter",
                # CalculiX's block (prm/probe_indentation.prm now has a
                # larger one)
                "Mesh/Patch length x=105", "Mesh/Patch length y=68"]
    for layer, n in zip(LAYERS, across):
        settings += [f"Layer stack/{layer}/Material model=linear",
                     f"Layer stack/{layer}/Young's modulus={MODULI[layer]}",
                     f"Layer stack/{layer}/Poisson's ratio={nu}",
                     f"Layer stack/{layer}/Cells across={n}",
                     f"Layer stack/{layer}/Grading=1"]
    start = time.time()
    done = ssc_runner.run(PRM, settings, folder, name, check=True)
    wall = time.time() - start
    s = done.summary()
    strains = s["layer_strain_under_centre_per_step"]
    return dict(degree=degree, cell_size=h, edge_size=edge, grading=grading,
                cells_across="/".join(map(str, across)), nu=nu,
                dofs=s["dofs"], K_N_per_mm=s["force_N"][-1],
                strain_skin=strains["skin"][-1],
                strain_fat=strains["fat"][-1],
                strain_muscle=strains["muscle"][-1], wall_s=f"{wall:.2f}")


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for nu in sorted({float(r["nu"]) for r in rows}):
        for degree, marker in [(1, "o"), (2, "s")]:
            sel = [r for r in rows if float(r["nu"]) == nu and
                   int(r["degree"]) == degree]
            if not sel:
                continue
            for ax, key in zip(axes, ["error_K", "error_strain_fat"]):
                ax.loglog([float(r["wall_s"]) for r in sel],
                          [abs(float(r[key])) for r in sel], marker=marker,
                          ls="none", label=f"Q{degree}, nu = {nu}")
    for ax, title in zip(axes, ["stiffness", "fat strain under the centre"]):
        ax.axhline(0.01, color="gray", lw=0.8, ls="--")
        ax.set_xlabel("wall time, one core [s]")
        ax.set_ylabel("|relative error| against CalculiX")
        ax.set_title(title)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "probe_convergence.png"), dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--nu", type=float, nargs="+", default=[0.49, 0.3])
    parser.add_argument("--plot-only", action="store_true",
                        help="replot results/probe_convergence.csv")
    args = parser.parse_args()
    if args.plot_only:
        plot(list(csv.DictReader(open(os.path.join(
            OUT, "probe_convergence.csv")))))
        return
    rows = []
    with ssc_runner.scratch() as folder:
        for nu in args.nu:
            ref = reference(nu)
            for mesh in MESHES:
                row = run_ssc(nu, mesh, folder)
                row["error_K"] = f"{row['K_N_per_mm'] / ref['K_N_per_mm'] - 1:.2e}"
                for layer in ["fat", "muscle"]:
                    key = f"strain_{layer}"
                    row[f"error_{key}"] = f"{row[key] / ref[key] - 1:.2e}"
                rows.append(row)
                print(row, flush=True)
    with open(os.path.join(OUT, "probe_convergence.csv"), "w",
              newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    plot(rows)


if __name__ == "__main__":
    main()
