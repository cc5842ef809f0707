#!/usr/bin/python3
"""Plots results/multigrid_layered.csv: CG iterations of the geometric
multigrid and the AMG preconditioner against the DoFs of the layered punch
(Q1, nu 0.3, contrast 1:60), one line per lateral coarse cell count."""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(HERE, "results",
                                             "multigrid_layered.csv"))))
fig, ax = plt.subplots(figsize=(6.4, 4.2))
for lateral, colour in (("6", "C0"), ("12", "C1"), ("24", "C2")):
    for method, style in (("gmg", "o-"), ("amg", "s--")):
        sel = [r for r in rows if r["degree"] == "1" and r["nu"] == "0.3"
               and r["contrast"] == "60" and r["lateral_cells"] == lateral
               and r["method"] == method]
        if not sel:
            continue
        ax.plot([int(r["dofs"]) for r in sel],
                [int(r["iterations"]) for r in sel], style, color=colour,
                label=f"{method}, {lateral} coarse cells "
                      f"(SM aspect {120 // int(lateral)})")
ax.set_xscale("log")
ax.set_xlabel("DoFs (Q1, uniform refinements of the layered coarse mesh)")
ax.set_ylabel("CG iterations to 1e-8")
ax.set_title("Layered punch, nu 0.3, contrast 1:60")
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(HERE, "results", "multigrid_layered.png"), dpi=120)
