#!/usr/bin/python3
"""Plots an identification run: measured against predicted surface
stiffness of the held-out subjects, per site, for the finite-element model
with the fitted population moduli and for the springs-in-series baseline,
with the median absolute errors; the same for the fat and muscle strains
at the largest force; and, where the run made them
(person_predictions.csv), the held-out stiffness of every site predicted by
each method: the population model, the same recalibrated to the training
stiffnesses (one factor for all), the per-person ones (covariates, the
subject's other sites, both) and the springs.

    /usr/bin/python3 scripts/plot_identification.py output/identification

Writes identification_stiffness.png, identification_strains.png and
identification_person.png into the run folder.
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


def log_ticks(ax):
    """Labels at 1, 2 and 5 times the powers of ten on both log axes (a
    panel within one decade would otherwise have no label)."""
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1, 2, 5)))
        axis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        axis.set_minor_formatter(matplotlib.ticker.NullFormatter())


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
    log_ticks(ax)
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ax.set_xlabel("measured " + unit)
    ax.set_ylabel("predicted " + unit)
    ax.set_title(label, fontsize=9)
    ax.legend(fontsize=7, loc="upper left")


def site_grid(n_sites, rows_per_site=1):
    """A figure with one panel per site (and rows_per_site below each
    other), at most four sites in a row."""
    columns = min(n_sites, 4)
    site_rows = (n_sites + columns - 1) // columns
    fig, axes = plt.subplots(site_rows * rows_per_site, columns,
                             figsize=(3.6 * columns,
                                      3.6 * site_rows * rows_per_site),
                             squeeze=False)
    panels = [[axes[(k // columns) * rows_per_site + i][k % columns]
               for i in range(rows_per_site)] for k in range(n_sites)]
    for k in range(n_sites, site_rows * columns):
        for i in range(rows_per_site):
            axes[(k // columns) * rows_per_site + i][k % columns].axis("off")
    return fig, panels


METHODS = [("stiffness_model", "population FE model"),
           ("stiffness_calibrated", "FE, one factor for all"),
           ("stiffness_covariates", "FE x covariate factor"),
           ("stiffness_cross_site", "FE x other-site factor"),
           ("stiffness_covariates_and_cross_site", "FE x both factors"),
           ("stiffness_springs", "springs in series")]


def person_figure(folder, sites):
    """Measured against predicted held-out stiffness for each method, all
    sites in one panel per method, with its median absolute error."""
    path = os.path.join(folder, "person_predictions.csv")
    if not os.path.exists(path):
        return
    rows = [r for r in read_rows(path) if r["set"] == "held_out"]
    methods = [(key, label) for key, label in METHODS if key in rows[0]]
    columns = min(len(methods), 3)
    rows_of_panels = (len(methods) + columns - 1) // columns
    fig, axes = plt.subplots(rows_of_panels, columns,
                             figsize=(3.6 * columns, 3.6 * rows_of_panels),
                             squeeze=False)
    for k in range(len(methods), rows_of_panels * columns):
        axes.flat[k].axis("off")
    values = [float(r[key]) for r in rows
              for key in ["stiffness_measured_N_per_mm"] +
              [key for key, _ in methods]]
    lo, hi = 0.8 * min(values), 1.25 * max(values)
    for ax, (key, label) in zip(axes.flat, methods):
        ax.plot([lo, hi], [lo, hi], "k-", lw=0.8)
        errors = []
        for site in sites:
            site_rows = [r for r in rows if r["site"] == site]
            measured = np.array([float(r["stiffness_measured_N_per_mm"])
                                 for r in site_rows])
            predicted = np.array([float(r[key]) for r in site_rows])
            errors.extend(np.abs(predicted / measured - 1))
            ax.loglog(measured, predicted, "o", ms=3, label=site)
        log_ticks(ax)
        ax.set_xlim(lo, hi)
        ax.set_ylim(lo, hi)
        ax.set_xlabel("measured stiffness (N/mm)")
        ax.set_ylabel("predicted stiffness (N/mm)")
        ax.set_title("%s\nmedian |error| %.0f %% (%d held out)"
                     % (label, 100 * np.median(errors), len(errors)),
                     fontsize=9)
    axes[0][0].legend(fontsize=6, loc="upper left", ncol=2)
    fig.tight_layout()
    fig.savefig(run_manifest.record(folder, "identification_person.png"),
                dpi=120)


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
    fig, panels = site_grid(len(sites))
    for (ax,), site in zip(panels, sites):
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
    fig, panels = site_grid(len(sites), 2)
    for k, site in enumerate(sites):
        site_rows = [r for r in rows if r["site"] == site]
        for i, layer in enumerate(["fat", "muscle"]):
            panel(panels[k][i], column(site_rows, layer + "_strain_measured"),
                  column(site_rows, layer + "_strain_model"),
                  column(site_rows, layer + "_strain_springs"),
                  "%s, %s strain at the largest force" % (site, layer),
                  layer + " strain")
    fig.tight_layout()
    fig.savefig(run_manifest.record(folder, "identification_strains.png"),
                dpi=120)

    person_figure(folder, sites)


if __name__ == "__main__":
    main()
