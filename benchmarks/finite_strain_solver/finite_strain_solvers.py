#!/usr/bin/python3
"""Finite-strain indentation to 1.8 N: the AMG and the reused Cholesky
preconditioner (Elasticity/Linear solver/Preconditioner), with and without
the secant predictor of each load increment (Nonlinear solver/Predictor),
run one after the other in this script on this machine.

Cases:
- hard: hard_cases.prm (in this folder), reference case (8,262 DoFs, Q1
  mixed, neo-Hookean, microstructure, edge contact, bonded), one rank;
- forearm: prm/forearm_indentation_linear.prm at finite strain as in
  large_deformation.py (Q1 mixed, 58,983 DoFs, neo-Hookean,
  tension-field septa, tension-only ligaments, edge contact, bonded): AMG on
  2 ranks against Cholesky on one rank (it factorises on one process).

- ogrid: the main scene's layers (prm/forearm_indentation.prm without the
  microstructure) on the o-grid, Q2-P1 (33,075 DoFs), to 0.35 N only, one
  rank, Cholesky: the tangents that are not positive definite factorised as
  L D L^T (MUMPS) against preconditioned by AMG (Elasticity/Linear
  solver/Factor indefinite tangents), each twice, alternating.

Records depth at the last force, Newton and Krylov iterations, factorisations, the
assembly and solve times and the wall time. Writes
benchmarks/finite_strain_solver/results/finite_strain_solvers.csv (the
rows of cases not run stay).

    /usr/bin/python3 benchmarks/finite_strain_solver/finite_strain_solvers.py
        [--cases hard forearm ogrid]
"""
import argparse, csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

ROOT = ssc_runner.ROOT
OUT = os.path.join(HERE, "results")
LAYERS = ["skin", "SAT", "SM", "DAT", "deep"]
FIELDS = ["case", "preconditioner", "indefinite", "predictor", "ranks",
          "dofs", "depth_mm", "newton_iterations", "linear_iterations",
          "factorizations", "indefinite_factorizations", "t_assembly", "t_solve", "t_total", "wall_s",
          "memory_MB"]
FOREARM = ["Punch/Section=false", "Punch/Contact=bonded",
           "Elasticity/Formulation=mixed", "Elasticity/Degree=1",
           "Mesh/Region of interest/Local refinements=1",
           "Embedded/Septa/Tension field=true",
           "Embedded/Ligaments/Tension only=true",
           "Punch/Edge contact=true"] + \
    [f"Layer stack/{l}/Material model=neo-Hookean" for l in LAYERS]
OGRID = ["Mesh/Layout=o-grid", "Mesh/O-grid/Cells around=8",
         "Mesh/O-grid/Edge cell size=0.3", "Mesh/O-grid/Radial grading=1.6",
         "Mesh/O-grid/Grade in depth=true", "Elasticity/Degree=2",
         "Elasticity/Formulation=mixed", "Microstructure/Lobules=false",
         "Microstructure/Ligaments/Enabled=false", "Punch/Forces=0.35",
         # the scene's punch as it was when this was measured: the whole
         # face bonded, the mesh circle at its radius, contact factor 100
         "Mesh/Fitted circle radius=2.5", "Punch/Tied region=whole face",
         "Punch/Contact penalty=100",
         # the scene's mesh had no refinement level and no estimate then
         "Mesh/Global refinements=0", "Punch/Depth error estimate=none"]
CASES = {"hard": (os.path.join(HERE, "hard_cases.prm"), []),
         "forearm": (os.path.join(ROOT, "prm", "forearm_indentation_linear.prm"),
                     FOREARM),
         "ogrid": (os.path.join(ROOT, "prm", "forearm_indentation.prm"),
                   OGRID)}


def run(case, preconditioner, predictor, ranks, folder, indefinite="ldlt",
        repeat=0):
    prm, settings = CASES[case]
    name = f"{case}_{preconditioner}_{indefinite}_{predictor}_{ranks}_{repeat}"
    overrides = ["Run/Write fields=false",
                 f"Elasticity/Linear solver/Preconditioner={preconditioner}",
                 "Elasticity/Linear solver/Factor indefinite tangents="
                 f"{'true' if indefinite == 'ldlt' else 'false'}",
                 f"Nonlinear solver/Predictor={predictor}"] + settings
    # mpirun only for several ranks, with its default binding of the ranks
    # to cores (bind=True), as these runs were measured
    done = ssc_runner.run(prm, overrides, folder, name,
                          ranks=ranks if ranks > 1 else None, bind=True,
                          timeout=3600)
    wall = done.wall_s
    if not done.ok:
        print(f"{name} failed: {done.stderr.strip()[:300]}", flush=True)
        return None
    s = done.summary()
    t, solver = s["timings"], s["solver"]
    row = dict(case=case, preconditioner=preconditioner,
               indefinite=indefinite if preconditioner == "cholesky" else "-",
               predictor=predictor, ranks=ranks, dofs=s["dofs"], depth_mm=s["depth_mm"][-1],
               newton_iterations=solver["newton_iterations"],
               linear_iterations=solver["linear_iterations"],
               factorizations=solver.get("cholesky_factorizations", 0),
               indefinite_factorizations=solver.get(
                   "indefinite_factorizations", 0),
               t_assembly=round(t["assembly"], 2),
               t_solve=round(t["solve"], 2), t_total=round(t["total"], 2),
               wall_s=round(wall, 1), memory_MB=round(s["memory_MB"]))
    print(" ".join(f"{k}={row[k]}" for k in FIELDS), flush=True)
    return row


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cases", nargs="+", choices=list(CASES),
                        default=list(CASES))
    args = parser.parse_args()
    plan = {"hard": [("amg", "none", 1), ("amg", "extrapolation", 1),
                     ("cholesky", "none", 1),
                     ("cholesky", "extrapolation", 1)],
            "forearm": [("amg", "extrapolation", 2),
                        ("cholesky", "extrapolation", 1)],
            "ogrid": [("cholesky", "extrapolation", 1, "ldlt", 0),
                      ("cholesky", "extrapolation", 1, "amg", 0),
                      ("cholesky", "extrapolation", 1, "ldlt", 1),
                      ("cholesky", "extrapolation", 1, "amg", 1)]}
    path = os.path.join(OUT, "finite_strain_solvers.csv")
    rows = []
    if os.path.exists(path):
        # the rows of the cases not run now stay
        with open(path) as f:
            rows = [r for r in csv.DictReader(f)
                    if r["case"] not in args.cases]
    with ssc_runner.scratch() as folder:
        for case in args.cases:
            for entry in plan[case]:
                row = run(case, *entry[:3], folder, *entry[3:])
                if row:
                    rows.append(row)
    with open(path, "w", newline="") as f:
        # rows from before a column existed leave it empty
        writer = csv.DictWriter(f, fieldnames=FIELDS, restval="")
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
