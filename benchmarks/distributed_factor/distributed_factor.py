#!/usr/bin/env python3
"""The sparse factor on one rank (CHOLMOD's Cholesky, Preconditioner =
cholesky) against MUMPS's L D L^T distributed over the MPI ranks
(Preconditioner = ldlt) on 1 and 2 ranks, side by side on this machine:
the layered punch of prm/punch.prm (Q2, linear) at Global refinements 0
and 1, and, with --main, the finite-strain forearm scene
(prm/forearm_indentation.prm). Each case writes one CSV row: wall time of
the whole run, its solve phase, peak memory (all ranks) and the answer
(stiffness, or the depth at the largest force), which must agree.

    python3 benchmarks/distributed_factor/distributed_factor.py [--main]
        [--refinements 0,1] [--repeat N]

(Debian's /usr/bin/python3, for matplotlib) writes results/distributed_factor.csv and results/distributed_factor.png.
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

# (label, preconditioner, ranks)
SETUPS = [("cholesky, 1 rank", "cholesky", 1),
          ("ldlt, 1 rank", "ldlt", 1),
          ("ldlt, 2 ranks", "ldlt", 2)]


def one_run(prm, overrides, name, preconditioner, ranks):
    settings = dict(overrides)
    settings["Elasticity/Linear solver/Preconditioner"] = preconditioner
    run = ssc_runner.run(prm, settings, output_dir=RUNS, name=name,
                         ranks=ranks if ranks > 1 else None, timeout=1800)
    if not run.ok:
        sys.exit(f"{name} failed:\n{run.stderr[-2000:]}")
    return run.summary()


def answer(summary):
    """The run's result that every set-up must reproduce."""
    if summary.get("control") == "force":  # the depth at the last force
        return summary["depth_mm"][-1]
    return summary["stiffness_N_per_mm"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--main", action="store_true",
                        help="also the forearm scene (about 3 x 100 s)")
    parser.add_argument("--refinements", default="0,1",
                        help="punch.prm Global refinements (default 0,1)")
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs per case; the fastest is kept")
    parser.add_argument("--plot-only", action="store_true",
                        help="redraw the PNG from the CSV")
    args = parser.parse_args()
    path = os.path.join(RESULTS, "distributed_factor.csv")
    if args.plot_only:
        with open(path) as f:
            plot([{k: (float(v) if k in ("wall_s", "memory_per_dof_kB")
                       else v) for k, v in row.items()}
                  for row in csv.DictReader(f)])
        return
    os.makedirs(RUNS, exist_ok=True)

    cases = [("punch, refinement " + r, os.path.join(
        ssc_runner.ROOT, "prm", "punch.prm"),
        {"Mesh/Global refinements": r}) for r in args.refinements.split(",")]
    if args.main:
        cases.append(("forearm (main scene)", os.path.join(
            ssc_runner.ROOT, "prm", "forearm_indentation.prm"), {}))

    rows = []
    for case, prm, overrides in cases:
        for label, preconditioner, ranks in SETUPS:
            best = None
            for repeat in range(args.repeat):
                name = (case.split()[0] + "_" + "_".join(
                    str(v) for v in overrides.values()) + "_" +
                    preconditioner + f"_{ranks}")
                s = one_run(prm, overrides, name, preconditioner, ranks)
                if best is None or \
                        s["timings"]["total"] < best["timings"]["total"]:
                    best = s
            row = {"case": case, "setup": label, "dofs": best["dofs"],
                   "ranks": ranks,
                   "wall_s": round(best["timings"]["total"], 2),
                   "solve_s": round(best["timings"].get("solve", 0.), 2),
                   "assembly_s": round(best["timings"].get("assembly", 0.),
                                       2),
                   "memory_MB": round(best["memory_MB"], 1),
                   "memory_per_dof_kB": round(best["memory_per_dof_kB"], 2),
                   "newton_iterations": best["solver"]["newton_iterations"],
                   "answer": answer(best)}
            rows.append(row)
            print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)

    ssc_runner.write_rows(path, rows)
    plot(rows)


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = list(dict.fromkeys(r["case"] for r in rows))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    width = 0.8 / len(SETUPS)
    for k, (label, _, _) in enumerate(SETUPS):
        picked = [next(r for r in rows
                       if r["case"] == c and r["setup"] == label)
                  for c in cases]
        x = [i + (k - 1) * width for i in range(len(cases))]
        axes[0].bar(x, [r["wall_s"] for r in picked], width, label=label)
        axes[1].bar(x, [r["memory_per_dof_kB"] for r in picked], width,
                    label=label)
    for ax, title in zip(axes, ["wall time of the run [s]",
                                "peak memory per DoF [kB]"]):
        ax.set_xticks(range(len(cases)))
        ax.set_xticklabels([f"{c}\n{next(r['dofs'] for r in rows if r['case'] == c)} DoFs"
                            for c in cases], fontsize=8)
        ax.set_title(title)
        ax.grid(axis="y", alpha=0.3)
    axes[0].set_yscale("log")
    axes[0].legend()
    fig.suptitle("Sparse factor on one rank (CHOLMOD) against MUMPS "
                 "distributed over the ranks, 2-core machine")
    fig.tight_layout()
    path = os.path.join(RESULTS, "distributed_factor.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()
