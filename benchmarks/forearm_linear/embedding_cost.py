#!/usr/bin/python3
"""Cost of the embedded microstructure in the forearm punch
(forearm_punch.prm in this folder, one core): for septum triangle sizes 4,
2, 1 and 0.5 mm and without septa/ligaments, the number of embedded quadrature
points (the triangles are split along the background cells), the time to
split them, the extra assembly time per point, CG iterations (septa 100
times stiffer than fat), stiffness, DoFs and wall time. Writes
benchmarks/forearm_linear/results/embedding_cost.csv and .png.

    /usr/bin/python3 benchmarks/forearm_linear/embedding_cost.py
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

PRM = os.path.join(HERE, "forearm_punch.prm")
OUT = os.path.join(HERE, "results")
CASES = [("layers only", {"Microstructure/Lobules": "false",
                          "Microstructure/Ligaments": "false"}),
         ("ligaments only", {"Microstructure/Lobules": "false"})] + \
        [(f"septa {h} mm + ligaments",
          {"Microstructure/Septum triangle size": str(h)})
         for h in (4, 2, 1, 0.5)]
FIELDS = ["case", "dofs", "septa_triangles", "septa_points", "ligament_points",
          "cg_iterations", "stiffness_N_per_mm", "t_microstructure",
          "t_embedding", "t_clip", "t_assembly", "t_solve", "t_total",
          "clip_us_per_point", "assembly_us_per_point"]


def run(label, overrides, folder):
    # the run's name is the prm's (forearm_punch)
    ssc_runner.run(PRM, overrides, folder, check=True)
    s = ssc_runner.read_summary(os.path.join(folder, "forearm_punch"))
    e, t = s["embedded"], s["timings"]
    points = e.get("septa_quadrature_points", 0) + \
        e.get("ligament_quadrature_points", 0)
    return dict(case=label, dofs=s["dofs"],
                septa_triangles=e["septa_triangles"],
                septa_points=e.get("septa_quadrature_points", 0),
                ligament_points=e.get("ligament_quadrature_points", 0),
                cg_iterations=s["solver"]["linear_iterations"],
                stiffness_N_per_mm=s["stiffness_N_per_mm"],
                t_microstructure=t["microstructure"],
                t_embedding=t["embedding"], t_clip=e.get("clip_seconds", 0),
                t_assembly=t["assembly"], t_solve=t["solve"],
                t_total=t["total"], points=points)


def main():
    rows = []
    with ssc_runner.scratch() as folder:
        for label, overrides in CASES:
            rows.append(run(label, overrides, folder))
            print(f"{label:26s} {rows[-1]['cg_iterations']:4d} CG, "
                  f"k = {rows[-1]['stiffness_N_per_mm']:.5f} N/mm, "
                  f"{rows[-1]['points']:7d} points, "
                  f"{rows[-1]['t_total']:.1f} s", flush=True)
    base = rows[0]
    for r in rows:
        n = max(r.pop("points"), 1)
        r["clip_us_per_point"] = 1e6 * r["t_clip"] / n
        r["assembly_us_per_point"] = \
            1e6 * (r["t_assembly"] - base["t_assembly"]) / n
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, "embedding_cost.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    septa = [r for r in rows if r["septa_points"] > 0]
    x = [r["septa_points"] for r in septa]
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    ax[0].loglog(x, [r["t_clip"] for r in septa], "o-",
                 label="split along the cells")
    ax[0].loglog(x, [r["t_assembly"] - base["t_assembly"] for r in septa],
                 "s-", label="extra assembly")
    ax[0].set_xlabel("septa quadrature points")
    ax[0].set_ylabel("wall time [s]")
    ax[0].legend()
    ax[1].semilogx(x, [r["cg_iterations"] for r in septa], "o-",
                   label="with septa")
    ax[1].axhline(base["cg_iterations"], color="k", ls="--",
                  label="layers only")
    ax[1].axhline(1.5 * base["cg_iterations"], color="r", ls=":",
                  label="target: 1.5 x layers only")
    ax[1].set_xlabel("septa quadrature points")
    ax[1].set_ylabel("CG iterations")
    ax[1].legend(fontsize=8)
    ax[2].semilogx(x, [r["stiffness_N_per_mm"] for r in septa], "o-",
                   label="septa + ligaments")
    ax[2].axhline(base["stiffness_N_per_mm"], color="k", ls="--",
                  label="layers only")
    ax[2].set_xlabel("septa quadrature points")
    ax[2].set_ylabel("stiffness [N/mm]")
    ax[2].legend(fontsize=8)
    for a in ax:
        a.grid(True, which="both", alpha=0.3)
    fig.suptitle("Forearm punch: cost and effect of the embedded septa "
                 "(1 core)")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "embedding_cost.png"), dpi=110)


if __name__ == "__main__":
    main()
