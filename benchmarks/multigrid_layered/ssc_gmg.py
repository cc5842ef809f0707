#!/usr/bin/env python3
"""ssc's geometric multigrid preconditioner (Preconditioner = gmg) against
the Cholesky factor and AMG, side by side on this machine, through the ssc
executable: the layered punch of prm/punch_large.prm (five layers, SM cells
of aspect 20, Q1, nu 0.3) at 1, 2 and 3 global refinements (5.6k, 39k,
295k DoFs) and, with --large, gmg alone at 4 (2.3M DoFs, about 6 GB).
Each run writes one CSV row: wall time of the whole run, its solve phase
(set-up of the preconditioner included), CG iterations, peak memory per
DoF and the stiffness, which must agree.

    python3 benchmarks/multigrid_layered/ssc_gmg.py [--large]

(Debian's /usr/bin/python3, for matplotlib) writes results/ssc_gmg.csv and
results/ssc_gmg.png.
"""
import argparse
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

RESULTS = os.path.join(HERE, "results")
RUNS = os.path.join(RESULTS, "runs")
PRM = os.path.join(ssc_runner.ROOT, "prm", "punch_large.prm")
PRECONDITIONERS = ["gmg", "cholesky", "amg"]


def one_run(refinements, preconditioner):
    name = f"punch_large_{refinements}_{preconditioner}"
    run = ssc_runner.run(
        PRM, {"Mesh/Global refinements": refinements,
              "Elasticity/Linear solver/Preconditioner": preconditioner},
        output_dir=RUNS, name=name, timeout=3600)
    if not run.ok:
        sys.exit(f"{name} failed:\n{run.stderr[-2000:]}")
    s = run.summary()
    ssc_runner.remove(os.path.join(RUNS, name))
    return {"preconditioner": preconditioner, "refinements": refinements,
            "dofs": s["dofs"], "wall_s": round(s["timings"]["total"], 2),
            "solve_s": round(s["timings"]["solve"], 2),
            "assembly_s": round(s["timings"]["assembly"], 2),
            "cg_iterations": s["solver"]["linear_iterations"],
            "memory_MB": round(s["memory_MB"], 1),
            "memory_per_dof_kB": round(s["memory_per_dof_kB"], 2),
            "stiffness_N_per_mm": s["stiffness_N_per_mm"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--large", action="store_true",
                        help="also gmg at 4 refinements (2.3M DoFs)")
    parser.add_argument("--plot-only", action="store_true",
                        help="redraw the PNG from the CSV")
    args = parser.parse_args()
    path = os.path.join(RESULTS, "ssc_gmg.csv")
    if args.plot_only:
        with open(path) as f:
            plot(list(csv.DictReader(f)))
        return
    os.makedirs(RUNS, exist_ok=True)
    rows = []
    for refinements in (1, 2, 3):
        for preconditioner in PRECONDITIONERS:
            rows.append(one_run(refinements, preconditioner))
            print(rows[-1], flush=True)
    if args.large:
        rows.append(one_run(4, "gmg"))
        print(rows[-1], flush=True)
    ssc_runner.write_rows(path, rows)
    plot(rows)


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for preconditioner in PRECONDITIONERS:
        picked = [r for r in rows if r["preconditioner"] == preconditioner]
        dofs = [int(r["dofs"]) for r in picked]
        axes[0].plot(dofs, [float(r["wall_s"]) for r in picked], "o-",
                     label=preconditioner)
        axes[1].plot(dofs, [float(r["memory_per_dof_kB"]) for r in picked],
                     "o-", label=preconditioner)
    for ax, title in zip(axes, ["wall time of the run [s]",
                                "peak memory per DoF [kB]"]):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("DoFs (Q1)")
        ax.set_title(title)
        ax.grid(alpha=0.3)
        ax.legend()
    fig.suptitle("ssc on prm/punch_large.prm: multigrid (gmg) against "
                 "Cholesky and AMG, one rank")
    fig.tight_layout()
    out = os.path.join(RESULTS, "ssc_gmg.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
