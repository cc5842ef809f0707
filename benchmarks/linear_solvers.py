#!/usr/bin/python3
"""Iterations, time and memory of the linear solvers on the layered punch.

Runs build/bin/ssc on prm/punch.prm (skin, SAT, SM, DAT, muscle with the
reference moduli, 1:60 contrast, bonded punch under displacement control,
one linear solve) with every layer at nu = 0.3, 0.49 and 0.4999, for the
three Elasticity/Linear solver/Method values (cg: CG with AMG on the
condensed displacement system; block: FGMRES on the displacement-pressure
saddle point, AMG on the augmented deviatoric block; direct: MUMPS), Q1 and
Q2 mixed, over refinement levels towards the punch edge, one after the other
on one core of this machine. Writes benchmarks/results/linear_solvers.csv
and .png (iterations against DoFs).

    /usr/bin/python3 benchmarks/linear_solvers.py [--plot-only]
"""
import csv, json, os, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SSC = os.path.join(os.environ.get("SSC_BUILD_DIR", os.path.join(ROOT, "build")),
                   "bin", "ssc")
PRM = os.path.join(ROOT, "prm", "punch.prm")
OUT = os.path.join(ROOT, "benchmarks", "results")
LAYERS = ["skin", "SAT", "SM", "DAT", "deep"]
LEVELS = {1: [2, 3], 2: [1, 2]}  # local refinements towards the punch edge
FIELDS = ["method", "degree", "nu", "level", "dofs", "iterations",
          "stiffness_N_per_mm", "t_assembly", "t_solve", "t_total",
          "memory_MB", "memory_at_start_MB"]


def run(method, degree, nu, level, folder):
    name = f"{method}_q{degree}_nu{nu}_l{level}"
    args = [SSC, PRM, "-s", f"Run/Output directory={folder}",
            "-s", f"Run/Name={name}", "-s", "Run/Write fields=false",
            "-s", f"Elasticity/Linear solver/Method={method}",
            "-s", "Elasticity/Linear solver/Max iterations=2000",
            "-s", f"Elasticity/Degree={degree}",
            "-s", f"Mesh/Region of interest/Local refinements={level}"]
    for layer in LAYERS:
        args += ["-s", f"Layer stack/{layer}/Poisson's ratio={nu}"]
    try:
        done = subprocess.run(args, capture_output=True, text=True,
                              timeout=900)
    except subprocess.TimeoutExpired:
        print(f"{name}: stopped after 900 s", flush=True)
        return None
    if done.returncode != 0:
        print(f"{name} failed: {done.stderr.strip()[:200]}", flush=True)
        return None
    with open(os.path.join(folder, name, "summary.json")) as f:
        s = json.load(f)
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
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, degree in zip(axes, (1, 2)):
        # one colour per nu, one line style per method (a missing point:
        # the solver did not converge within its limits)
        for method, style, marker in (("cg", "-", "o"), ("block", "--", "s")):
            for nu, colour in ((0.3, "C0"), (0.49, "C1"), (0.4999, "C2")):
                pts = sorted((r["dofs"], r["iterations"]) for r in rows
                             if r["method"] == method and r["degree"] == degree
                             and abs(r["nu"] - nu) < 1e-9)
                if pts:
                    ax.plot(*zip(*pts), style, color=colour, marker=marker,
                            label=f"{method}, nu = {nu}")
        ax.set_xscale("log")
        ax.set_xlabel("DoFs")
        ax.set_ylabel("Krylov iterations")
        ax.set_title(f"layered punch, Q{degree} mixed")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "linear_solvers.png"), dpi=120)


def main():
    path = os.path.join(OUT, "linear_solvers.csv")
    if "--plot-only" not in sys.argv:
        rows = []
        with tempfile.TemporaryDirectory() as folder:
            for degree, levels in LEVELS.items():
                for level in levels:
                    for nu in (0.3, 0.49, 0.4999):
                        for method in ("cg", "block", "direct"):
                            # MUMPS through Amesos: minutes and GBs at Q2
                            if method == "direct" and degree == 2 and \
                                    level > 1:
                                continue
                            row = run(method, degree, nu, level, folder)
                            if row:
                                rows.append(row)
        with open(path, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=FIELDS)
            writer.writeheader()
            writer.writerows(rows)
    with open(path) as f:
        rows = [dict(r, degree=int(r["degree"]), nu=float(r["nu"]),
                     dofs=int(r["dofs"]), iterations=int(r["iterations"]))
                for r in csv.DictReader(f)]
    plot(rows)


if __name__ == "__main__":
    main()
