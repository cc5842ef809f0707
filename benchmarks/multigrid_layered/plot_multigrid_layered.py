#!/usr/bin/python3
"""Plots results/multigrid_layered.csv: CG iterations of the geometric
multigrid and the AMG preconditioner against the DoFs of the layered punch
(Q1, nu 0.3, contrast 1:60), one line per coarse mesh (the aspect ratio of
the thinnest layer's cells) and smoother."""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(HERE, "results",
                                             "multigrid_layered.csv"))))
fig, ax = plt.subplots(figsize=(9.6, 4.6))
# (lateral cells, smoother degree, equal layers): colour, label
series = {("6", "4", "0"): ("C0", "punch layers, SM aspect 20"),
          ("6", "8", "0"): ("C3", "punch layers, SM aspect 20, Chebyshev 8"),
          ("12", "4", "0"): ("C1", "punch layers, SM aspect 10"),
          ("24", "4", "0"): ("C2", "punch layers, SM aspect 5"),
          ("8", "4", "1"): ("C4", "five 3.6 mm layers, aspect 2")}
for (lateral, smoother, equal), (colour, label) in series.items():
    for method, style in (("gmg", "o-"), ("amg", "s--")):
        if method == "amg" and smoother != "4":
            continue  # the smoother degree is the multigrid's only
        sel = [r for r in rows if r["degree"] == "1" and r["nu"] == "0.3"
               and r["contrast"] == "60" and r["lateral_cells"] == lateral
               and r["smoother_degree"] == smoother
               and r["equal_layers"] == equal and r["method"] == method]
        if not sel:
            continue
        ax.plot([int(r["dofs"]) for r in sel],
                [int(r["iterations"]) for r in sel], style, color=colour,
                label=f"{method}: {label}")
ax.set_xscale("log")
ax.set_xlabel("DoFs (Q1, uniform refinements of the layered coarse mesh)")
ax.set_ylabel("CG iterations to 1e-8")
ax.set_title("Layered punch, nu 0.3, contrast 1:60")
ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5))
fig.tight_layout()
fig.savefig(os.path.join(HERE, "results", "multigrid_layered.png"), dpi=120)
