#!/usr/bin/python3
"""Iterations, time and memory of the linear solvers on the layered punch.

Runs build/bin/ssc on prm/punch.prm with its earlier box mesh (skin, SAT, SM, DAT, muscle with the
reference moduli, 1:60 contrast, bonded punch under displacement control,
one linear solve) with every layer at nu = 0.3, 0.49 and 0.4999, for the
linear solvers (cg: CG with AMG on the condensed displacement system;
block: FGMRES on the displacement-pressure saddle point, AMG on the
augmented deviatoric block; cholesky: CG preconditioned by the sparse
Cholesky factor of the matrix, Linear solver/Preconditioner = cholesky;
direct: MUMPS), Q1 and Q2 mixed, over refinement levels towards the punch
edge, one after the other on one core of this machine. Writes
benchmarks/linear_solvers/results/linear_solvers.csv and .png (iterations
and solve time against DoFs). --methods and --degrees run a subset: its
rows replace those of the same method, degree, nu and level in the CSV.

    /usr/bin/python3 benchmarks/linear_solvers/linear_solvers.py
        [--methods M ...] [--degrees 1 2] [--plot-only]
"""
import argparse, csv, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

ROOT = ssc_runner.ROOT
PRM = os.path.join(ROOT, "prm", "punch.prm")
OUT = os.path.join(HERE, "results")
LAYERS = ["skin", "SAT", "SM", "DAT", "deep"]
LEVELS = {1: [2, 3], 2: [1, 2]}  # local refinements towards the punch edge
# the mesh these tables were measured on (prm/punch.prm had it until it
# moved to the o-grid): 5 mm cells fitted to the punch circle, refined
# towards its edge, more AMG smoothing for the thin stiff layers
BOX_MESH = ["Mesh/Layout=box", "Mesh/Cell size=5",
            "Mesh/Region of interest/Ring radius=2.5",
            "Mesh/Region of interest/Width=10",
            "Mesh/Region of interest/Shrink factor=0.5",
            "Elasticity/Linear solver/Smoother sweeps=4"]
FIELDS = ["method", "degree", "nu", "level", "dofs", "iterations",
          "stiffness_N_per_mm", "t_assembly", "t_solve", "t_total",
          "memory_MB", "memory_at_start_MB"]


def run(method, degree, nu, level, folder):
    name = f"{method}_q{degree}_nu{nu}_l{level}"
    solver = {"cholesky": ["Elasticity/Linear solver/Method=cg",
                           "Elasticity/Linear solver/Preconditioner=cholesky"]
              }.get(method, [f"Elasticity/Linear solver/Method={method}",
                             "Elasticity/Linear solver/Preconditioner=amg"])
    settings = ["Run/Write fields=false", solver[0], solver[-1],
                "Elasticity/Linear solver/Max iterations=2000",
                f"Elasticity/Degree={degree}",
                f"Mesh/Region of interest/Local refinements={level}"]
    settings += BOX_MESH
    settings += [f"Layer stack/{layer}/Poisson's ratio={nu}"
                 for layer in LAYERS]
    try:
        done = ssc_runner.run(PRM, settings, folder, name, timeout=900)
    except subprocess.TimeoutExpired:
        print(f"{name}: stopped after 900 s", flush=True)
        return None
    if not done.ok:
        print(f"{name} failed: {done.stderr.strip()[:200]}", flush=True)
        return None
    s = done.summary()
    t = s["timings"]
    row = dict(method=method, degree=degree, nu=nu, level=level,
               dofs=s["dofs"], iterations=s["solver"]["linear_iterations"],
               stiffness_N_per_mm=s["stiffness_N_per_mm"],
               t_assembly=t["assembly"], t_solve=t["solve"],
               t_total=t["total"], memory_MB=s["memory_MB"],
               memory_at_start_MB=s["memory_at_start_MB"])
    print(" ".join(f"{k}={row[k]}" for k in FIELDS), flush=True)
    return row


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5))
    styles = {"cg": ("-", "o"), "block": ("--", "s"),
              "cholesky": (":", "^"), "direct": ("-.", "x")}
    for column, degree in enumerate((1, 2)):
        # one colour per nu, one line style per method (a missing point:
        # the solver did not converge within its limits, or was not run)
        for row, (key, label) in enumerate((("iterations", "Krylov iterations"),
                                            ("t_solve", "solve time (s)"))):
            ax = axes[row][column]
            for method, (style, marker) in styles.items():
                if key == "iterations" and method in ("cholesky", "direct"):
                    continue
                for nu, colour in ((0.3, "C0"), (0.49, "C1"), (0.4999, "C2")):
                    pts = sorted((r["dofs"], float(r[key])) for r in rows
                                 if r["method"] == method and
                                 r["degree"] == degree and
                                 abs(r["nu"] - nu) < 1e-9)
                    if pts:
                        ax.plot(*zip(*pts), style, color=colour,
                                marker=marker, label=f"{method}, nu = {nu}")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("DoFs")
            ax.set_ylabel(label)
            ax.set_title(f"layered punch, Q{degree} mixed, one core")
            ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "linear_solvers.png"), dpi=120)


def read(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [dict(r, degree=int(r["degree"]), nu=float(r["nu"]),
                     level=int(r["level"]), dofs=int(r["dofs"]),
                     iterations=int(r["iterations"]))
                for r in csv.DictReader(f)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--methods", nargs="+",
                        choices=["cg", "block", "cholesky", "direct"],
                        default=["cg", "block", "cholesky", "direct"])
    parser.add_argument("--degrees", nargs="+", type=int, choices=[1, 2],
                        default=[1, 2])
    parser.add_argument("--plot-only", action="store_true")
    args = parser.parse_args()
    path = os.path.join(OUT, "linear_solvers.csv")
    rows = read(path)
    if not args.plot_only:
        done = set()
        new_rows = []
        with ssc_runner.scratch() as folder:
            for degree in args.degrees:
                for level in LEVELS[degree]:
                    for nu in (0.3, 0.49, 0.4999):
                        for method in args.methods:
                            done.add((method, degree, nu, level))
                            # the sparse factorisations at Q2 200k DoFs:
                            # minutes and GBs (not run)
                            if method in ("direct", "cholesky") and \
                                    degree == 2 and level > 1:
                                continue
                            row = run(method, degree, nu, level, folder)
                            if row:
                                new_rows.append(row)
        rows = [r for r in rows if (r["method"], r["degree"], r["nu"],
                                    r["level"]) not in done] + new_rows
        with open(path, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=FIELDS)
            writer.writeheader()
            writer.writerows(rows)
        rows = read(path)
    plot(rows)


if __name__ == "__main__":
    main()
