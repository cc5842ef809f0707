#!/usr/bin/python3
"""Plots results/multigrid_line.csv (run_multigrid_layered.sh): on the
layered punch with SM cells of aspect 20, the CG iterations against the
DoFs of every preconditioner side by side and of the line-smoothed V-cycle
over nu and contrast (left), and the time to solve (set-up plus CG, right)."""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(HERE, "results",
                                             "multigrid_line.csv"))))
LABELS = {"gmg": "V-cycle, point Jacobi Chebyshev",
          "gmg-line": "V-cycle, line Chebyshev",
          "amg": "ML AMG", "cholesky": "Cholesky (CHOLMOD)"}
COLOURS = {"gmg": "C0", "gmg-line": "C3", "amg": "C2", "cholesky": "C7"}
fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8))
for method, label in LABELS.items():
    for degree, style in (("1", "o-"), ("2", "s--")):
        sel = [r for r in rows if r["study"] == "side_by_side"
               and r["method"] == method and r["degree"] == degree]
        if not sel:
            continue
        dofs = [int(r["dofs"]) for r in sel]
        if method != "cholesky":
            left.plot(dofs, [int(r["iterations"]) for r in sel], style,
                      color=COLOURS[method], label=f"{label}, Q{degree}")
        right.plot(dofs, [float(r["setup_s"]) + float(r["solve_s"])
                          for r in sel], style, color=COLOURS[method],
                   label=f"{label}, Q{degree}")
# the line-smoothed V-cycle over nu and contrast (Q1, the sweep)
for (nu, contrast), colour in ((("0.49", "60"), "C1"), (("0.3", "1000"), "C4"),
                               (("0.4999", "60"), "C5")):
    sel = [r for r in rows if r["study"] == "sweep" and r["degree"] == "1"
           and r["nu"] == nu and r["contrast"] == contrast]
    if sel:
        left.plot([int(r["dofs"]) for r in sel],
                  [int(r["iterations"]) for r in sel], "^:", color=colour,
                  label=f"line Chebyshev, Q1, nu {sel[0]['nu']}, "
                        f"1:{contrast}")
largest = [r for r in rows if r["study"] == "largest"]
if largest:
    left.plot([int(r["dofs"]) for r in largest],
              [int(r["iterations"]) for r in largest], "x", color="k",
              label="line Chebyshev, Q1, to 2.3M DoFs")
for axis in (left, right):
    axis.set_xscale("log")
    axis.set_xlabel("DoFs (uniform refinements of the layered coarse mesh)")
left.set_yscale("log")
left.set_ylabel("CG iterations to 1e-8")
right.set_yscale("log")
right.set_ylabel("set-up + solve (s), one core")
left.set_title("Layered punch, SM cells of aspect 20")
right.set_title("Time to solve, nu 0.3, contrast 1:60")
left.legend(fontsize=6.5)
right.legend(fontsize=6.5)
fig.tight_layout()
fig.savefig(os.path.join(HERE, "results", "multigrid_line.png"), dpi=120)
