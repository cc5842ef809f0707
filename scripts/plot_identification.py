#!/usr/bin/python3
"""Plots an identification run: measured against predicted surface
stiffness of the held-out subjects, per site, for the finite-element model
with the fitted population moduli and for the springs-in-series baseline,
with the median absolute errors; and the same for the fat and muscle
strains at the largest force.

    /usr/bin/python3 scripts/plot_identification.py output/identification

Writes identification_stiffness.png and identification_strains.png into the
run folder.
"""
import csv, json, os, sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.ticker

import run_manifest  # noqa: E402 (scripts/)


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def panel(ax, measured, model, springs, label, unit):
    # log axes: a few measured compressions are zero or negative
    keep = (measured > 0) & (model > 0) & (springs > 0)
    measured, model, springs = measured[keep], model[keep], springs[keep]
    lo = 0.8 * min(measured.min(), model.min(), springs.min())
    hi = 1.25 * max(measured.max(), model.max(), springs.max())
    ax.plot([lo, hi], [lo, hi], "k-", lw=0.8)
    err = lambda p: np.median(np.abs(p / measured - 1)) * 100
    ax.loglog(measured, model, "o", ms=4,
              label="ssc FE, fitted moduli (%.0f %%)" % err(model))
    ax.loglog(measured, springs, "x", ms=4,
              label="springs in series (%.0f %%)" % err(springs))
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ax.set_xlabel("measured " + unit)
    ax.set_ylabel("predicted " + unit)
    ax.set_title(label, fontsize=9)
    ax.legend(fontsize=7, loc="upper left")


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "output/identification"
    rows = [r for r in read_rows(os.path.join(folder, "identification.csv"))
            if r["set"] == "held_out"]
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    sites = list(summary["identification"].keys())

    def column(site_rows, name):
        return np.array([float(r[name]) for r in site_rows])

    # stiffness
    fig, axes = plt.subplots(1, len(sites), figsize=(3.6 * len(sites), 3.6),
                             squeeze=False)
    for ax, site in zip(axes[0], sites):
        site_rows = [r for r in rows if r["site"] == site]
        E = summary["identification"][site]["moduli_MPa"]
        panel(ax, column(site_rows, "stiffness_measured_N_per_mm"),
              column(site_rows, "stiffness_model"),
              column(site_rows, "stiffness_springs"),
              "%s, %d held out\nskin %.3g, fat %.3g, muscle %.3g kPa"
              % (site, len(site_rows), 1e3 * E["skin"], 1e3 * E["fat"],
                 1e3 * E["muscle"]), "stiffness (N/mm)")
    fig.tight_layout()
    fig.savefig(run_manifest.record(folder, "identification_stiffness.png"),
                dpi=120)

    # fat and muscle strains
    fig, axes = plt.subplots(2, len(sites), figsize=(3.6 * len(sites), 7.0),
                             squeeze=False)
    for k, site in enumerate(sites):
        site_rows = [r for r in rows if r["site"] == site]
        for i, layer in enumerate(["fat", "muscle"]):
            panel(axes[i][k], column(site_rows, layer + "_strain_measured"),
                  column(site_rows, layer + "_strain_model"),
                  column(site_rows, layer + "_strain_springs"),
                  "%s, %s strain at the largest force" % (site, layer),
                  layer + " strain")
    fig.tight_layout()
    fig.savefig(run_manifest.record(folder, "identification_strains.png"),
                dpi=120)


if __name__ == "__main__":
    main()
