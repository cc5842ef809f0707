#!/usr/bin/python3
"""How good are the error bars the main scene computes? prm/forearm_indentation.prm
estimates the discretisation error of its depth at each force from a
second path on the mesh with one global refinement fewer (Punch/Depth
error estimate = coarser mesh): with d_h its depth and d_2h the coarser
one's, e = (d_h - d_2h) / (2^1.5 - 1). Here the scene's estimate is set
against the error it estimates:

- the reference: the same scene refined once more (Mesh/Global
  refinements = 2: 32 cells around, 0.1 mm at the edge circle, 166k DoFs),
  same lobules, septa and ligaments, on the V-cycle;
- from the three nested meshes (2h, h, h/2) the observed order of
  convergence p = log2((d_h - d_2h) / (d_h/2 - d_h)) at each force and
  Richardson's limit d = d_h/2 + (d_h/2 - d_h) / (2^p - 1): the error of
  the scene's depth is d - d_h, and the effectivity index of its estimate
  is e / (d - d_h) (1: exact; the issue asks for 0.5-2);
- a second, independent reference where it exists: Q2-P1 on the 8-around
  o-grid of the convergence study (forearm_convergence.csv, 33k DoFs, to
  1.5 N; itself not converged, so it bounds the error from below).

The Herlin-moduli variant (prm/forearm_indentation_herlin2014.prm) is run
with its own computed bars (no reference: its fat is 30 times softer).

Writes benchmarks/forearm/results/depth_error_effectivity.csv (one row per
force: the three depths, the estimate, the observed order, the limit, the
effectivity, the Q2-P1 depth; and the scenes' wall times) and
depth_error_effectivity.png. Every run uses 2 MPI ranks; the runs are kept
in results/runs/depth_error/ and not repeated (delete a folder to rerun).
The reference takes about 40 minutes alone on this machine.

    /usr/bin/python3 benchmarks/forearm/depth_error_effectivity.py
    /usr/bin/python3 benchmarks/forearm/depth_error_effectivity.py --plot-only
"""
import csv, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402
# a run stopped short: what its progress lines (log.txt) say it reached
from forearm_finite_strain import stopped_run  # noqa: E402

ROOT = ssc_runner.ROOT
SCENE = os.path.join(ROOT, "prm", "forearm_indentation.prm")
HERLIN = os.path.join(ROOT, "prm", "forearm_indentation_herlin2014.prm")
OUT = os.path.join(HERE, "results")
RUNS = os.path.join(OUT, "runs", "depth_error")
CSV = os.path.join(OUT, "depth_error_effectivity.csv")
CONVERGENCE = os.path.join(OUT, "forearm_convergence.csv")
QUIET = ["Run/Write fields=false", "Punch/Section=false",
         "Punch/Profile length=0"]
# (case, prm, overrides)
CASES = [
    ("scene", SCENE, []),
    ("reference (refined once more)", SCENE,
     ["Mesh/Global refinements=2", "Punch/Depth error estimate=none"]),
    ("herlin scene", HERLIN, []),
]
ASSUMED_ORDER = 1.5  # CoarserMeshDepthEstimate::assumed_order


def run(case, prm, overrides):
    """The case's summary, run on 2 ranks unless kept; a run that failed
    or was stopped by hand (its output kept as log.txt in its folder) gives
    the forces it reached (None if none)."""
    folder = os.path.join(RUNS, case.split()[0])
    summary = os.path.join(folder, "summary.json")
    if not os.path.exists(summary) and \
            not os.path.exists(os.path.join(folder, "log.txt")):
        with ssc_runner.scratch() as tmp:
            print("running", case, flush=True)
            result = ssc_runner.run(prm, QUIET + overrides, tmp, "run",
                                    ranks=2, timeout=4 * 3600)
            os.makedirs(folder, exist_ok=True)
            if result.ok:
                ssc_runner.keep(result.folder, folder)
            else:
                print(f"{case}: failed: {result.stderr[-300:]}")
                with open(os.path.join(folder, "log.txt"), "w") as f:
                    f.write(result.stdout + result.stderr)
    if os.path.exists(summary):
        return ssc_runner.read_summary(folder)
    return stopped_run(folder)


def q2p1_depths():
    """{force: depth} of the convergence study's Q2-P1 run (8 around)."""
    with open(CONVERGENCE) as f:
        for row in csv.DictReader(f):
            if (row["contact"], row["discretisation"], row["mesh"]) == \
                    ("bonded", "Q2-P1", "n8 h0.3"):
                return {float(k[len("depth_mm_at_"):-1]): float(v)
                        for k, v in row.items()
                        if k.startswith("depth_mm_at_") and v}
    return {}


def measure():
    summaries = {case: run(case, prm, overrides)
                 for case, prm, overrides in CASES}
    scene = summaries["scene"]
    reference = summaries["reference (refined once more)"]
    herlin = summaries["herlin scene"]
    q2p1 = q2p1_depths()
    factor = 2 ** ASSUMED_ORDER - 1
    rows = []
    for k, force in enumerate(scene["force_N"]):
        d_h = scene["depth_mm"][k]
        estimate = scene["depth_error_estimate_mm"][k]
        row = dict(force_N=force, depth_2h_mm=d_h - estimate * factor,
                   depth_h_mm=d_h, estimate_mm=estimate,
                   estimate_pct=100 * estimate / d_h)
        d_half = reference["depth_mm"][k] if reference and \
            k < len(reference["depth_mm"]) else None
        row["depth_h/2_mm"] = "" if d_half is None else d_half
        row.update({key: "" for key in
                    ["observed_order", "limit_mm", "error_mm", "error_pct",
                     "effectivity", "estimate_of_h/2_pct"]})
        if d_half is not None:
            ratio = (d_h - row["depth_2h_mm"]) / (d_half - d_h)
            order = math.log2(ratio) if ratio > 1 else float("nan")
            limit = d_half + (d_half - d_h) / (2 ** order - 1)
            # the bar the refined scene would compute, and its share
            row.update({"observed_order": order, "limit_mm": limit,
                        "error_mm": limit - d_h,
                        "error_pct": 100 * (limit - d_h) / d_h,
                        "effectivity": estimate / (limit - d_h),
                        "estimate_of_h/2_pct":
                            100 * (d_half - d_h) / factor / d_half})
        q2 = q2p1.get(round(force, 6))
        row["q2p1_8_around_mm"] = "" if q2 is None else q2
        row["effectivity_vs_q2p1"] = "" if q2 is None else \
            estimate / (q2 - d_h)
        if herlin:
            row["herlin_depth_mm"] = herlin["depth_mm"][k]
            row["herlin_estimate_mm"] = herlin["depth_error_estimate_mm"][k]
        rows.append(row)
        print({key: round(v, 4) if isinstance(v, float) else v
               for key, v in row.items()}, flush=True)
    for case, s in summaries.items():
        if s and s.get("stopped_short"):
            print(f"{case}: {s['dofs']} DoFs, stopped short at "
                  f"{s['force_N'][-1]} N after "
                  f"{s['solver']['newton_iterations']} Newton iterations")
        elif s:
            print(f"{case}: {s['dofs']} DoFs, wall {s['timings']['total']:.1f}"
                  f" s (error estimate "
                  f"{s['timings'].get('error estimate', 0):.1f} s), "
                  f"{s['solver']['newton_iterations']} Newton")
    ssc_runner.write_rows(CSV, rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(CSV) as f:
        # empty cells (no reference at that force) as NaN: not drawn
        rows = [{k: float(v) if v not in ("", None) else math.nan
                 for k, v in r.items()} for r in csv.DictReader(f)]
    force = [r["force_N"] for r in rows]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5))
    ax.plot([r["depth_2h_mm"] for r in rows], force, "s:", color="0.6",
            label="coarser mesh (8 around, 2,916 DoFs)")
    ax.errorbar([r["depth_h_mm"] for r in rows], force,
                xerr=[abs(r["estimate_mm"]) for r in rows], fmt="o-",
                capsize=3, label="the scene (16 around, 21,597 DoFs) with "
                "its computed bars")
    ax.plot([r["depth_h/2_mm"] for r in rows], force, "^-",
            label="refined once more (32 around, 166,455 DoFs)")
    ax.plot([r["limit_mm"] for r in rows], force, "k--",
            label="Richardson limit (observed order)")
    q2 = [(r["q2p1_8_around_mm"], r["force_N"]) for r in rows
          if not math.isnan(r["q2p1_8_around_mm"])]
    ax.plot(*zip(*q2), "D", mfc="none", color="tab:red",
            label="Q2-P1, 8 around (33,075 DoFs)")
    ax.set_xlabel("depth [mm]")
    ax.set_ylabel("force [N]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    ax.set_title("the main scene's depth on three nested meshes", fontsize=9)
    bx.plot(force, [r["effectivity"] for r in rows], "o-",
            label="against the Richardson limit")
    bx.plot(*zip(*[(r["force_N"], r["effectivity_vs_q2p1"]) for r in rows
                   if not math.isnan(r["effectivity_vs_q2p1"])]), "D:",
            mfc="none", color="tab:red", label="against Q2-P1, 8 around")
    bx.axhspan(0.5, 2, color="tab:green", alpha=0.15,
               label="0.5-2 (the issue's range)")
    bx.axhline(1, color="k", lw=0.8)
    bx.set_xlabel("force [N]")
    bx.set_ylabel("effectivity index (estimate / error)")
    bx.set_ylim(0, 2.5)
    bx.grid(alpha=0.3)
    bx.legend(fontsize=7)
    bx.set_title("the computed error bar against the error", fontsize=9)
    fig.tight_layout()
    path = os.path.join(OUT, "depth_error_effectivity.png")
    fig.savefig(path, dpi=110)
    print("wrote", os.path.relpath(path, ROOT))


if __name__ == "__main__":
    if "--plot-only" not in sys.argv:
        measure()
    plot()
