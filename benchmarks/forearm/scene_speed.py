#!/usr/bin/python3
"""What the main scene's septum quadrature and its threads buy, measured
side by side: the scene (prm/forearm_indentation.prm) to its first three
forces (0.35, 0.5, 0.75 N) on one MPI rank, with the septa integrated with
2 Gauss points per direction on each piece in a cell (the default) or with
1 (the scene's choice), and the cell loops on one thread
(DEAL_II_NUM_THREADS=1) or on every core (the scene, as `./ssc.sh run`
runs it). Each configuration runs REPEATS times, the configurations
alternating, so that the shared machine's load falls on all of them
alike. Writes benchmarks/forearm/results/scene_speed.csv (wall, assembly
and solve seconds, Newton iterations, depths) and scene_speed.png.

    /usr/bin/python3 benchmarks/forearm/scene_speed.py [--plot-only]
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402
# the scene's discretisation when this was measured
from newton_path import SCENE_UNTIL_2026_12_06  # noqa: E402

ROOT = ssc_runner.ROOT
SCENE = os.path.join(ROOT, "prm", "forearm_indentation.prm")
OUT = os.path.join(HERE, "results")
CSV = os.path.join(OUT, "scene_speed.csv")
FORCES = "0.35, 0.5, 0.75"
REPEATS = 3
# (label, septa Gauss points per direction, threads: None = every core)
CONFIGURATIONS = [("septa 2 points, 1 thread", 2, 1),
                  ("septa 1 point, 1 thread", 1, 1),
                  ("septa 1 point, every core (scene)", 1, None)]


def run(septa_points, threads):
    env = dict(os.environ)
    env.pop("DEAL_II_NUM_THREADS", None)
    if threads is not None:
        env["DEAL_II_NUM_THREADS"] = str(threads)
    with ssc_runner.scratch() as tmp:
        result = ssc_runner.run(
            SCENE, ["Run/Write fields=false", "Punch/Section=false",
                    "Punch/Profile length=0", f"Punch/Forces={FORCES}",
                    *SCENE_UNTIL_2026_12_06,
                    f"Embedded/Septa/Quadrature points={septa_points}"],
            tmp, "run", env=env)
        if not result.ok:
            sys.exit(result.stdout + result.stderr)
        return result.summary()


def measure():
    rows = []
    for repeat in range(REPEATS):
        for label, points, threads in CONFIGURATIONS:
            s = run(points, threads)
            t = s["timings"]
            row = {"configuration": label, "repeat": repeat + 1,
                   "septa_points": points,
                   "threads": s["threads_per_rank"],
                   "wall_s": round(t["total"], 2),
                   "assembly_s": round(t["assembly"], 2),
                   "solve_s": round(t["solve"], 2),
                   "newton_iterations": s["solver"]["newton_iterations"],
                   "septa_quadrature_points":
                       s["embedded"]["septa_quadrature_points"]}
            for f, d in zip(s["force_N"], s["depth_mm"]):
                row[f"depth_mm_at_{f:g}N"] = d
            rows.append(row)
            print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)
    ssc_runner.write_rows(CSV, rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    labels = [c[0] for c in CONFIGURATIONS]
    fig, ax = plt.subplots(figsize=(7, 3.5))
    for i, label in enumerate(labels):
        runs = [r for r in rows if r["configuration"] == label]
        for j, r in enumerate(runs):
            y = i + 0.35 * (j - (len(runs) - 1) / 2)
            ax.barh(y, float(r["assembly_s"]), 0.3, color="tab:blue",
                    label="assembly" if i == j == 0 else None)
            ax.barh(y, float(r["solve_s"]), 0.3, left=float(r["assembly_s"]),
                    color="tab:orange", label="solve" if i == j == 0 else None)
    ax.set_yticks(range(len(labels)), labels, fontsize=8)
    ax.set_xlabel("wall time [s], scene to 0.75 N, one MPI rank")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis="x")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "scene_speed.png"), dpi=110)
    print("wrote benchmarks/forearm/results/scene_speed.png")


if __name__ == "__main__":
    if "--plot-only" not in sys.argv:
        measure()
    plot()
