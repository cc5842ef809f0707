"""Can the main scene compute its own error bars by one richer step?

    /usr/bin/python3 benchmarks/forearm/error_estimate.py [--plot-only]

Punch/Depth error estimate = enriched degree estimates the discretisation
error of the depth at each force by one Newton step of Q2-P0 (Q2 with the
cell's mean dilatation) on the same mesh from the converged Q1-P0 state:
the dual-weighted residual estimate with the adjoint in the richer space.
It is exact for linear layers (tests/depth_error_estimate). This runs the
main scene (prm/forearm_indentation.prm, finite strain) with it on the
o-grids of 8 and 12 cells around (the scene's) and records, per force, the
estimate or that there is none (null in summary.json: the Q2-P0 tangent at
the Q1 state is indefinite, so one step follows negative curvature and
estimates nothing), beside the full Q2-P1 solve on the 8-around o-grid of
the convergence study (results/forearm_convergence.csv, to 1.5 N).

Writes results/error_estimate.csv and .png; one rank with threads, about
5 minutes alone on this 2-core machine.
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402
# the scene's discretisation when this was measured
from newton_path import SCENE_UNTIL_2026_12_06  # noqa: E402

SCENE = os.path.join(ssc_runner.ROOT, "prm", "forearm_indentation.prm")
OUT = os.path.join(HERE, "results")
CSV = os.path.join(OUT, "error_estimate.csv")
CONVERGENCE = os.path.join(OUT, "forearm_convergence.csv")
COMMON = ["Run/Write fields=false", "Punch/Section=false",
          "Punch/Profile length=0", *SCENE_UNTIL_2026_12_06,
          "Punch/Depth error estimate=enriched degree"]
# (label, o-grid: cells around, radial size at the circle, grading), as in
# forearm_finite_strain.py's convergence study
MESHES = [("n8 h0.3", 8, 0.3, 1.6), ("n12 h0.2 (the scene)", 12, 0.2, 1.4)]


def q2_reference():
    """{force: depth} of the kept Q2-P1 run on the 8-around o-grid."""
    with open(CONVERGENCE) as f:
        for row in csv.DictReader(f):
            if row["contact"] == "bonded" and \
                    row["discretisation"] == "Q2-P1" and \
                    row["mesh"] == "n8 h0.3":
                return {float(k[len("depth_mm_at_"):-1]): float(v)
                        for k, v in row.items()
                        if k.startswith("depth_mm_at_") and v}
    return {}


def measure():
    reference = q2_reference()
    rows = []
    for label, around, edge, grading in MESHES:
        overrides = COMMON + [f"Mesh/O-grid/Cells around={around}",
                              f"Mesh/O-grid/Edge cell size={edge}",
                              f"Mesh/O-grid/Radial grading={grading}"]
        with ssc_runner.scratch() as tmp:
            result = ssc_runner.run(SCENE, overrides, tmp, "run",
                                    timeout=3600)
            if not result.ok:
                print(f"{label}: failed: {result.stderr[-300:]}")
                continue
            s = result.summary()
        timings = s["timings"]
        for force, depth, change in zip(s["force_N"], s["depth_mm"],
                                        s["depth_error_estimate_mm"]):
            q2 = reference.get(force) if label.startswith("n8 ") else None
            rows.append(dict(
                mesh=label, dofs=s["dofs"],
                q2p0_dofs=s["depth_uncertainty_dofs"], force_N=force,
                depth_mm=round(depth, 4),
                # None: the Q2-P0 tangent at the state is indefinite
                estimate_mm="" if change is None else round(change, 4),
                q2p1_run_depth_mm="" if q2 is None else q2,
                wall_s=round(timings["total"], 1),
                estimate_s=round(timings["error estimate"], 1)))
            print(rows[-1], flush=True)
    ssc_runner.write_rows(CSV, rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    fig, ax = plt.subplots(figsize=(7, 4.8))
    for mesh, marker in zip(dict.fromkeys(r["mesh"] for r in rows), "os"):
        mine = [r for r in rows if r["mesh"] == mesh]
        ax.plot([float(r["depth_mm"]) for r in mine],
                [float(r["force_N"]) for r in mine], marker + "-",
                label=f"Q1-P0 {mesh} ({mine[0]['dofs']} DoFs)")
        given = [r for r in mine if r["estimate_mm"]]
        if given:
            ax.plot([float(r["depth_mm"]) + float(r["estimate_mm"])
                     for r in given], [float(r["force_N"]) for r in given],
                    marker, mfc="none",
                    label="  + its one-step Q2-P0 estimate")
        missing = [r for r in mine if not r["estimate_mm"]]
        if missing:
            ax.plot([float(r["depth_mm"]) for r in missing],
                    [float(r["force_N"]) for r in missing], "x",
                    color="tab:red", ms=9,
                    label="  no estimate: Q2-P0 tangent indefinite"
                    if marker == "o" else None)
    q2 = [r for r in rows if r["q2p1_run_depth_mm"]]
    ax.plot([float(r["q2p1_run_depth_mm"]) for r in q2],
            [float(r["force_N"]) for r in q2], "k*", ms=9,
            label="Q2-P1 n8 h0.3, full solve (33,075 DoFs)")
    ax.set_xlabel("depth [mm]")
    ax.set_ylabel("force [N]")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    ax.set_title("The main scene's one-step Q2-P0 error estimate (finite "
                 "strain)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "error_estimate.png"), dpi=110)
    print("wrote", os.path.join(OUT, "error_estimate.png"))


if __name__ == "__main__":
    if "--plot-only" not in sys.argv:
        measure()
    plot()
