#!/usr/bin/env python3
"""Nearly incompressible layers on the multigrid V-cycle (issue 45: Krylov
iterations <= 40, flat over three refinements, nu 0.3 -> 0.4999 in every
layer, contrast 1:1000, Q1 and Q2).

The layered punch of prm/punch_large.prm (five layers, the 0.5 mm SM,
bonded punch) on a coarser base mesh (3 x 3 cells of 20 mm laterally, one
cell per layer), with the same Poisson's ratio in every layer, solved by
the ssc executable in two ways, both with Preconditioner = gmg:

- block: the displacement-pressure saddle point of the mixed formulation
  (Q2-P1disc, and Q1-P0 for Q1) by FGMRES with the block-triangular
  preconditioner: the V-cycle on the displacement block, which carries a
  bulk modulus of at most 8 mu whatever nu, and the cells' pressure blocks
  M / (2 mu + gamma) + C for the Schur complement;
- cg: CG on the displacement system with the pressure condensed (the same
  discretisation and the same displacement), the V-cycle on the whole
  tangent, bulk modulus included.

Q1 at 2, 3, 4 refinements and Q2 at 1, 2, 3 (about 10k, 77k and 600k DoFs
each); cg only on the two smaller meshes (it needs hundreds of iterations
at nu 0.4999 and would take minutes at 600k). Each run writes one CSV row:
Krylov iterations (a run that needs more than 1000 is recorded as not
converged), wall time of the run, its solve phase (the preconditioner's
set-up included), peak memory per DoF and the stiffness, which the two
methods must give alike.

    /usr/bin/python3 benchmarks/multigrid_layered/nearly_incompressible.py

writes results/nearly_incompressible.csv and .png (about 35 minutes on one
core; --methods block reruns the block rows only, --plot-only redraws the
PNG from the CSV).
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
CSV = os.path.join(RESULTS, "nearly_incompressible.csv")
LAYERS = ["skin", "SAT", "SM", "DAT", "deep"]
POISSON = [0.3, 0.49, 0.4999]
# contrast name: the SM layer's Young's modulus (fat 0.001 MPa)
CONTRASTS = {"1:60": 0.06, "1:1000": 1.0}
REFINEMENTS = {1: (2, 3, 4), 2: (1, 2, 3)}
MAX_ITERATIONS = 1000


def overrides(degree, refinements, nu, sm_modulus, method):
    settings = {"Mesh/Cell size": 20,
                "Mesh/Global refinements": refinements,
                "Elasticity/Degree": degree,
                "Elasticity/Formulation": "mixed",
                "Elasticity/Linear solver/Preconditioner": "gmg",
                "Elasticity/Linear solver/Method": method,
                "Elasticity/Linear solver/Max iterations": MAX_ITERATIONS,
                "Layer stack/SM/Young's modulus": sm_modulus}
    for layer in LAYERS:
        settings[f"Layer stack/{layer}/Poisson's ratio"] = nu
    return settings


def one_run(degree, refinements, nu, contrast, method):
    name = f"nearly_incompressible_q{degree}_{refinements}_{nu}_" \
           f"{contrast.replace(':', '-')}_{method}"
    run = ssc_runner.run(
        PRM, overrides(degree, refinements, nu, CONTRASTS[contrast], method),
        output_dir=RUNS, name=name, timeout=3600)
    row = {"degree": degree, "refinements": refinements, "nu": nu,
           "contrast": contrast, "method": method, "converged": 0,
           "dofs": "", "iterations": MAX_ITERATIONS, "wall_s": "",
           "solve_s": "", "memory_per_dof_kB": "", "stiffness_N_per_mm": ""}
    if not run.ok:
        if "did not converge" not in run.stderr:
            sys.exit(f"{name} failed:\n{run.stderr[-2000:]}")
        ssc_runner.remove(os.path.join(RUNS, name))
        return row
    s = run.summary()
    ssc_runner.remove(os.path.join(RUNS, name))
    row.update({"converged": 1, "dofs": s["dofs"],
                "iterations": s["solver"]["linear_iterations"],
                "wall_s": round(s["timings"]["total"], 2),
                "solve_s": round(s["timings"]["solve"], 2),
                "memory_per_dof_kB": round(s["memory_per_dof_kB"], 2),
                "stiffness_N_per_mm": s["stiffness_N_per_mm"]})
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--plot-only", action="store_true",
                        help="redraw the PNG from the CSV")
    parser.add_argument("--methods", nargs="+", default=["block", "cg"],
                        choices=["block", "cg"],
                        help="run only these; the CSV's rows of the others "
                             "are kept")
    args = parser.parse_args()
    kept = []
    if os.path.exists(CSV):
        with open(CSV) as f:
            kept = [typed(r) for r in csv.DictReader(f)
                    if r["method"] not in args.methods]
    if args.plot_only:
        plot(kept)
        return
    os.makedirs(RUNS, exist_ok=True)
    rows = list(kept)
    for degree, levels in REFINEMENTS.items():
        for contrast in CONTRASTS:
            for nu in POISSON:
                for index, refinements in enumerate(levels):
                    methods = ["block", "cg"] if index < 2 else ["block"]
                    for method in set(methods) & set(args.methods):
                        rows.append(one_run(degree, refinements, nu,
                                            contrast, method))
                        print(rows[-1], flush=True)
                        rows.sort(key=order)
                        ssc_runner.write_rows(CSV, rows)
    check_stiffness(rows)
    plot(rows)


def typed(row):
    """A CSV row with the numbers the script compares as numbers."""
    row = dict(row)
    for key in ("degree", "refinements", "converged", "iterations"):
        row[key] = int(row[key])
    row["nu"] = float(row["nu"])
    if row["stiffness_N_per_mm"]:
        row["stiffness_N_per_mm"] = float(row["stiffness_N_per_mm"])
    return row


def order(row):
    """Rows in the order of the sweep: degree, contrast, nu, refinements,
    block before cg."""
    return (row["degree"], list(CONTRASTS).index(row["contrast"]),
            row["nu"], row["refinements"], row["method"])


def check_stiffness(rows):
    """block and cg solve the same discrete problem: their stiffness must
    agree to the solver tolerance."""
    for row in rows:
        if row["method"] != "cg" or not row["converged"]:
            continue
        twin = [r for r in rows if r["method"] == "block" and all(
            r[k] == row[k] for k in ("degree", "refinements", "nu",
                                     "contrast"))][0]
        difference = abs(twin["stiffness_N_per_mm"] /
                         row["stiffness_N_per_mm"] - 1)
        if difference > 1e-5:
            sys.exit(f"block and cg differ by {difference:.1e}: {row}")


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 4, figsize=(16, 4.2), sharey=True)
    styles = {0.3: "o", 0.49: "s", 0.4999: "^"}
    for ax, (degree, contrast) in zip(
            axes, [(d, c) for d in REFINEMENTS for c in CONTRASTS]):
        for method, line in (("block", "-"), ("cg", ":")):
            for nu, marker in styles.items():
                picked = [r for r in rows if int(r["degree"]) == degree
                          and r["contrast"] == contrast
                          and r["method"] == method
                          and float(r["nu"]) == nu]
                picked.sort(key=lambda r: int(r["refinements"]))
                ax.plot([int(r["refinements"]) for r in picked],
                        [int(r["iterations"]) for r in picked],
                        marker + line, label=f"{method}, nu {nu}")
                for r in picked:
                    if not int(r["converged"]):
                        ax.annotate("not converged",
                                    (int(r["refinements"]),
                                     int(r["iterations"])), fontsize=7)
        ax.axhline(40, color="k", lw=0.8, ls="--")
        ax.set_yscale("log")
        ax.set_xticks(REFINEMENTS[degree])
        ax.set_xlabel("global refinements")
        ax.set_title(f"Q{degree}-P{degree - 1}, contrast {contrast}")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("Krylov iterations to 1e-8 (dashed: 40)")
    axes[-1].legend(fontsize=7)
    fig.suptitle("Layered punch, every layer at the same nu: FGMRES with "
                 "the block preconditioner (V-cycle on the displacement "
                 "block) against CG with the V-cycle on the condensed "
                 "system")
    fig.tight_layout()
    out = os.path.join(RESULTS, "nearly_incompressible.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
