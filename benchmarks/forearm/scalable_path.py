#!/usr/bin/python3
"""Can the main scene run on the scalable solver? prm/forearm_indentation.prm
to 1.8 N on a mesh with a refinement level (its o-grid at half the
resolution, 8 cells around, 0.4 mm at the edge circle, grading 1.96,
refined once: 16 around, 0.2 mm, about 1.4 per cell), solved with the
sparse Cholesky factor on one rank (the scene's solver) and with the
geometric multigrid V-cycle (Galerkin levels with the septa, ligaments
and contact inside; line-block Chebyshev smoothing; MUMPS on the coarse
mesh) on one rank and on two; beside them the shipped scene (12 around,
0.2 mm, no refinement level, Cholesky). The runs alternate, one after the
other, on this machine; each rank count uses both cores (threads on one
rank, one thread per rank on two).

Each run's log is read for the tangents that were not positive definite
and for the solves in which the V-cycle could not be built (AMG instead).

Writes benchmarks/forearm/results/scalable_path.csv: per run the DoFs,
wall, assembly and solve times, Newton and Krylov iterations, indefinite
tangents, V-cycle fallbacks, and the depths at the seven forces; and
scalable_path.png: each variant's wall, assembly and solve times (median
run, the range of the wall times).

    /usr/bin/python3 benchmarks/forearm/scalable_path.py [repetitions]
    /usr/bin/python3 benchmarks/forearm/scalable_path.py --plot-only
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402
# the scene without fields, section or profile, and how its log is read
from newton_path import COMMON, SCENE, log_counts  # noqa: E402

CSV = os.path.join(HERE, "results", "scalable_path.csv")
REFINED = ["Mesh/O-grid/Cells around=8", "Mesh/O-grid/Edge cell size=0.4",
           "Mesh/O-grid/Radial grading=1.96", "Mesh/Global refinements=1"]
GMG = ["Elasticity/Linear solver/Preconditioner=gmg"]
# (label, overrides, MPI ranks or None)
VARIANTS = [
    ("scene: 12 around, cholesky, 1 rank", [], None),
    ("16 around (8 refined once), cholesky, 1 rank", REFINED, None),
    ("16 around (8 refined once), gmg, 1 rank", REFINED + GMG, None),
    ("16 around (8 refined once), gmg, 2 ranks", REFINED + GMG, 2),
]


def measure(repetitions):
    rows = []
    for repetition in range(repetitions):
        for label, overrides, ranks in VARIANTS:
            with ssc_runner.scratch() as tmp:
                result = ssc_runner.run(SCENE, COMMON + overrides, tmp,
                                        "run", ranks=ranks, timeout=3600)
                if not result.ok:
                    print(f"{label}: failed: {result.stderr[-300:]}")
                    continue
                s = result.summary()
            log = result.stdout
            solver, timings = s["solver"], s["timings"]
            row = dict(
                variant=label, repetition=repetition, dofs=s["dofs"],
                wall_s=round(timings["total"], 1),
                assembly_s=round(timings.get("assembly", 0.), 1),
                solve_s=round(timings.get("solve", 0.), 1),
                newton_iterations=solver["newton_iterations"],
                krylov_iterations=solver["linear_iterations"],
                indefinite_tangents=log_counts(log)["indefinite_tangents"],
                vcycle_fallbacks=log.count("AMG instead of the V-cycle"),
                depths_mm=" ".join(f"{d:.4f}" for d in s["depth_mm"]))
            print(row, flush=True)
            rows.append(row)
            ssc_runner.write_rows(CSV, rows)


def plot():
    """The CSV's runs as bars: per variant the median run's assembly and
    solve times and its wall time, whiskers over all its runs."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    labels = [label for label, _, _ in VARIANTS
              if any(r["variant"] == label for r in rows)]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for k, label in enumerate(labels):
        runs = sorted((r for r in rows if r["variant"] == label),
                      key=lambda r: float(r["wall_s"]))
        median = runs[len(runs) // 2]
        walls = [float(r["wall_s"]) for r in runs]
        for offset, key, colour in ((-0.25, "wall_s", "0.6"),
                                    (0., "assembly_s", "tab:blue"),
                                    (0.25, "solve_s", "tab:orange")):
            ax.bar(k + offset, float(median[key]), width=0.25, color=colour,
                   label=key.split("_")[0] if k == 0 else None)
        ax.plot([k - 0.25] * 2, [min(walls), max(walls)], color="k", lw=1)
        ax.text(k + 0.12, max(walls) + 4,
                f"{median['dofs']} DoFs\n{median['newton_iterations']} "
                "Newton", ha="center", fontsize=8)
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels([label.replace(", ", "\n", 1) for label in labels],
                       fontsize=8)
    ax.set_ylabel("time (s)")
    ax.set_title("forearm scene to 1.8 N: Cholesky factor against the "
                 "multigrid V-cycle", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(CSV.replace(".csv", ".png"), dpi=120)
    print("wrote", CSV.replace(".csv", ".png"))


if __name__ == "__main__":
    if sys.argv[1:] != ["--plot-only"]:
        measure(int(sys.argv[1]) if len(sys.argv) > 1 else 1)
    plot()
