#!/usr/bin/env python3
"""ssc's geometric multigrid preconditioner (Preconditioner = gmg) on one
and two MPI ranks against the Cholesky factor and AMG (one rank), side by
side on this machine, through the ssc executable: the layered punch of
prm/punch_large.prm (five layers, SM cells of aspect 20, Q1, nu 0.3) at 1,
2 and 3 global refinements (5.6k, 39k, 295k DoFs) and, with --large, gmg
alone at 4 (2.3M DoFs, about 6 GB). Each run writes one CSV row: wall
time of the whole run, its solve phase (set-up of the preconditioner
included), CG iterations, peak memory per DoF (all ranks) and the
stiffness, which must agree.

The ceiling of any two-rank speed-up on this machine is measured first
(results/two_process_ceiling.csv): one single-threaded, single-rank gmg
run at 295k DoFs alone, then two such independent runs at once. Where the
pair takes longer than one alone, the two cores do not do twice the work
of one on this kind of code (sparse matrices: memory-bound), and no
distributed solver can be 2 times faster on 2 ranks.

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
# (preconditioner, MPI ranks)
SETUPS = [("gmg", 1), ("gmg", 2), ("cholesky", 1), ("amg", 1)]


def throughput_ceiling(refinements=3):
    """The ceiling of any two-rank speed-up here: one single-threaded,
    single-rank gmg run alone, then two of them at once. Their ratio is
    the work two processes get done per second relative to one (2 on two
    independent cores)."""
    from concurrent.futures import ThreadPoolExecutor
    env = dict(os.environ, DEAL_II_NUM_THREADS="1")

    def timed(name):
        run = ssc_runner.run(
            PRM, {"Mesh/Global refinements": refinements},
            output_dir=RUNS, name=name, env=env, timeout=3600)
        if not run.ok:
            sys.exit(f"{name} failed:\n{run.stderr[-2000:]}")
        ssc_runner.remove(os.path.join(RUNS, name))
        return run.wall_s

    alone = timed("ceiling_alone")
    with ThreadPoolExecutor(2) as pool:
        pair = list(pool.map(timed, ["ceiling_a", "ceiling_b"]))
    return {"refinements": refinements, "alone_s": round(alone, 2),
            "pair_s": " ".join(f"{t:.2f}" for t in pair),
            "two_process_throughput": round(2 * alone / max(pair), 2)}


def one_run(refinements, preconditioner, ranks):
    name = f"punch_large_{refinements}_{preconditioner}_{ranks}"
    run = ssc_runner.run(
        PRM, {"Mesh/Global refinements": refinements,
              "Elasticity/Linear solver/Preconditioner": preconditioner},
        output_dir=RUNS, name=name, ranks=ranks, timeout=3600)
    if not run.ok:
        sys.exit(f"{name} failed:\n{run.stderr[-2000:]}")
    s = run.summary()
    ssc_runner.remove(os.path.join(RUNS, name))
    return {"preconditioner": preconditioner, "ranks": ranks,
            "refinements": refinements,
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
    ceiling = throughput_ceiling()
    print("two runs at once:", ceiling, flush=True)
    ssc_runner.write_rows(os.path.join(RESULTS, "two_process_ceiling.csv"),
                          [ceiling])
    rows = []
    for refinements in (1, 2, 3):
        for preconditioner, ranks in SETUPS:
            rows.append(one_run(refinements, preconditioner, ranks))
            print(rows[-1], flush=True)
    if args.large:
        for ranks in (1, 2):
            rows.append(one_run(4, "gmg", ranks))
            print(rows[-1], flush=True)
    ssc_runner.write_rows(path, rows)
    plot(rows)


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for preconditioner, ranks in SETUPS:
        picked = [r for r in rows if r["preconditioner"] == preconditioner
                  and int(r["ranks"]) == ranks]
        dofs = [int(r["dofs"]) for r in picked]
        label = f"{preconditioner}, {ranks} rank{'s' if ranks > 1 else ''}"
        axes[0].plot(dofs, [float(r["wall_s"]) for r in picked], "o-",
                     label=label)
        axes[1].plot(dofs, [float(r["memory_per_dof_kB"]) for r in picked],
                     "o-", label=label)
    for ax, title in zip(axes, ["wall time of the run [s]",
                                "peak memory per DoF, all ranks [kB]"]):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("DoFs (Q1)")
        ax.set_title(title)
        ax.grid(alpha=0.3)
        ax.legend()
    fig.suptitle("ssc on prm/punch_large.prm: multigrid (gmg) on 1 and 2 "
                 "ranks against Cholesky and AMG")
    fig.tight_layout()
    out = os.path.join(RESULTS, "ssc_gmg.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
