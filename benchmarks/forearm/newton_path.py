#!/usr/bin/python3
"""Where the main scene's Newton iterations go (on its discretisation until
2026-12-06, SCENE_UNTIL_2026_12_06), and what makes its tangents
indefinite: prm/forearm_indentation.prm to 1.8 N in variants that change
one thing each (the predictor, the size of the increments, the contact
penalty, depth instead of force control, the volumetric stabilisation, the
plain displacement formulation), run one after the other on one MPI rank.
Each run's log is read for

- the tangents that are not positive definite (each "not positive
  definite" line: a factorisation that found negative pivots), and how
  many of them were the tangent of a converged state: with Predictor =
  none an increment's first tangent is the last converged state's, so an
  indefinite one there would be an unstable equilibrium;
- the trust-region steps and how many of them were rejected.

Writes benchmarks/forearm/results/newton_path.csv (one row per variant:
Newton and CG iterations, indefinite tangents, trust-region steps, wall
time, depths at the seven forces or forces at the seven depths).

    /usr/bin/python3 benchmarks/forearm/newton_path.py ["variant" ...]

With arguments only the variants of those labels are run, and the CSV's
other rows are kept.
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

from main_scene import NO_PICTURES, SCENE  # noqa: E402,F401

CSV = os.path.join(HERE, "results", "newton_path.csv")
# the scene's discretisation until 2026-12-06, which these studies (and
# scalable_path.py's "scene" row, scene_speed.py, error_estimate.py,
# forearm_finite_strain.py) were made on: 12 around, 0.2 mm, grading 1.4,
# no refinement level, every tangent factorised, no error estimate
SCENE_UNTIL_2026_12_06 = [
    "Mesh/O-grid/Cells around=12", "Mesh/O-grid/Edge cell size=0.2",
    "Mesh/O-grid/Radial grading=1.4", "Mesh/Global refinements=0",
    "Elasticity/Linear solver/Preconditioner=cholesky",
    "Punch/Depth error estimate=none"]
COMMON = NO_PICTURES + SCENE_UNTIL_2026_12_06
DEPTH_CONTROL = ["Punch/Control=displacement", "Punch/Depth=11.05",
                 "Punch/Load steps=7"]
VARIANTS = [
    ("scene", []),
    ("predictor none", ["Nonlinear solver/Predictor=none"]),
    ("predictor none, fixed increments of 0.044 N",
     ["Nonlinear solver/Predictor=none", "Nonlinear solver/Initial steps=8",
      "Nonlinear solver/Growth factor=1"]),
    ("contact penalty 100", ["Punch/Contact penalty=100"]),
    ("contact penalty 30", ["Punch/Contact penalty=30"]),
    ("contact penalty 3000", ["Punch/Contact penalty=3000"]),
    ("contact penalty 10000", ["Punch/Contact penalty=10000"]),
    ("depth control to 11.05 mm in 7 steps", DEPTH_CONTROL),
    ("volumetric stabilisation 0.02",
     ["Elasticity/Volumetric stabilisation=0.02"]),
    ("displacement formulation (locks)",
     ["Elasticity/Formulation=displacement"]),
]


def log_counts(log):
    """Indefinite tangents (all, and at the start of an increment) and
    trust-region steps (all, rejected) in an ssc log."""
    lines = log.splitlines()
    indefinite = sum("not positive definite (" in line for line in lines)
    at_start = sum(1 for line, following in zip(lines, lines[1:])
                   if "Newton: residual" in line
                   and "not positive definite (" in following)
    steps = [line for line in lines if "trust region: step" in line]
    return dict(indefinite_tangents=indefinite,
                indefinite_at_increment_start=at_start,
                trust_region_steps=len(steps),
                rejected_trust_region_steps=sum("rejected" in line
                                                for line in steps))


def measure(only=()):
    """Runs the variants (those whose label is in only, if given) and
    writes their rows, keeping the CSV's rows of the others."""
    kept = []
    if only and os.path.exists(CSV):
        with open(CSV) as f:
            kept = [r for r in csv.DictReader(f) if r["variant"] not in only]
    rows = []
    for label, overrides in VARIANTS:
        if only and label not in only:
            continue
        with ssc_runner.scratch() as tmp:
            result = ssc_runner.run(SCENE, COMMON + overrides, tmp, "run",
                                    timeout=1800)
            if not result.ok:
                print(f"{label}: failed: {result.stderr[-300:]}")
                continue
            s = result.summary()
        solver = s["solver"]
        row = dict(variant=label, dofs=s["dofs"],
                   newton_iterations=solver["newton_iterations"],
                   cg_iterations=solver["linear_iterations"],
                   **log_counts(result.stdout),
                   wall_s=round(s["timings"]["total"], 1),
                   forces_N=" ".join(f"{f:.4f}" for f in s["force_N"]),
                   depths_mm=" ".join(f"{d:.4f}" for d in s["depth_mm"]))
        print(row, flush=True)
        rows.append(row)
    # in the order of VARIANTS
    order = [label for label, _ in VARIANTS]
    every = sorted(kept + rows, key=lambda r: order.index(r["variant"])
                   if r["variant"] in order else len(order))
    ssc_runner.write_rows(CSV, every)


if __name__ == "__main__":
    measure(sys.argv[1:])
