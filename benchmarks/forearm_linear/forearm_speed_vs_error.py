#!/usr/bin/python3
"""Speed versus error of the forearm indentation (prm/forearm_indentation_linear.prm,
bonded punch, linear elasticity): stiffness error against a converged value
versus wall time and DoFs, for Q1 displacement, Q1 mixed (B-bar), Q1
enhanced (B-bar plus incompatible modes) and Q2 mixed, layers only and with the microstructure (everywhere, or only in a
cylinder of radius 15 mm around the punch), plus the truncation of the
patch (the scene's 80 mm patch and a 60 mm one against patches twice as
large).

A level refines the mesh towards the punch edge (Mesh/Region of interest/
Local refinements) on 5 mm or 2.5 mm base cells. The converged stiffness of
each model is the Richardson extrapolation of its finest sequence on 2.5 mm
cells (layers: Q1 mixed; microstructure: Q1 enhanced), the rate estimated
from its last three levels. Timings
are wall times on one core, without writing field files; the best
configuration is also run on 2 MPI ranks.

Writes benchmarks/forearm_linear/results/forearm_speed_vs_error.csv, .png
and forearm_truncation.csv.

    /usr/bin/python3 benchmarks/forearm_linear/forearm_speed_vs_error.py
        [--plot-only]
"""
import csv, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

ROOT = ssc_runner.ROOT
PRM = os.path.join(ROOT, "prm", "forearm_indentation_linear.prm")
OUT = os.path.join(HERE, "results")
BASE = {"Run/Write fields": "false", "Punch/Control": "displacement",
        "Punch/Section": "false", "Punch/Profile length": "0"}
LAYERS = {"Microstructure/Lobules": "false",
          "Microstructure/Ligaments": "false"}
EVERYWHERE = {"Microstructure/Region of interest/Shape": "everywhere"}
ROI = {"Microstructure/Region of interest/Shape": "cylinder",
       "Microstructure/Region of interest/Radius": "15"}
Q1D = {"Elasticity/Formulation": "displacement"}
Q1M = {"Elasticity/Formulation": "mixed"}
Q1E = {"Elasticity/Formulation": "enhanced"}
Q2M = {"Elasticity/Degree": "2", "Elasticity/Formulation": "mixed"}
CS5 = {"Mesh/Cell size": "5"}
CS25 = {"Mesh/Cell size": "2.5"}
# (model, discretisation label, overrides, levels); the patch is the
# scene's 80 mm one (2.5 or 5 mm cells in the central 60 mm, graded outside)
CONFIGURATIONS = [
    ("layers", "Q1 mixed, 5 mm", {**LAYERS, **Q1M, **CS5}, [2, 3, 4, 5]),
    ("layers", "Q1 mixed, 2.5 mm", {**LAYERS, **Q1M, **CS25},
     [1, 2, 3, 4, 5]),
    ("layers", "Q1 displacement, 5 mm", {**LAYERS, **Q1D, **CS5},
     [2, 3, 4, 5]),
    ("layers", "Q1 enhanced, 5 mm", {**LAYERS, **Q1E, **CS5}, [2, 3, 4, 5]),
    ("layers", "Q1 enhanced, 2.5 mm", {**LAYERS, **Q1E, **CS25},
     [1, 2, 3, 4]),
    ("layers", "Q2 mixed, 5 mm", {**LAYERS, **Q2M, **CS5}, [1, 2]),
    ("microstructure", "Q1 mixed, 5 mm", {**EVERYWHERE, **Q1M, **CS5},
     [2, 3, 4, 5]),
    ("microstructure", "Q1 enhanced, 5 mm", {**EVERYWHERE, **Q1E, **CS5},
     [2, 3, 4, 5]),
    ("microstructure", "Q1 enhanced, 2.5 mm", {**EVERYWHERE, **Q1E, **CS25},
     [1, 2, 3, 4, 5]),
    ("microstructure", "Q1 enhanced, 2.5 mm, ROI r = 15 mm",
     {**ROI, **Q1E, **CS25}, [1, 2, 3, 4]),
    ("microstructure", "Q1 enhanced, 5 mm, ROI r = 15 mm",
     {**ROI, **Q1E, **CS5}, [2, 3, 4, 5]),
]
# the sequence whose Richardson extrapolation is the converged stiffness
REFERENCE = {"layers": "Q1 mixed, 2.5 mm",
             "microstructure": "Q1 enhanced, 2.5 mm"}
FIELDS = ["model", "discretisation", "level", "ranks", "dofs", "cells",
          "cg_iterations", "stiffness_N_per_mm", "converged_N_per_mm",
          "relative_error", "t_mesh", "t_microstructure", "t_embedding",
          "t_setup", "t_assembly", "t_solve", "t_total", "memory_MB"]


def run(overrides, folder, name, ranks=1):
    # mpirun (its ranks not bound to cores) only for several ranks
    return ssc_runner.run(PRM, {**BASE, **overrides}, folder, name,
                          ranks=ranks if ranks > 1 else None, check=True,
                          timeout=1800).summary()


def richardson(values):
    """Extrapolates the last three values of a sequence of halvings."""
    a, b, c = values[-3:]
    ratio = (c - b) / (b - a)
    if not 0 < ratio < 1:
        return c, float("nan")
    return c + (c - b) * ratio / (1 - ratio), -math.log2(ratio)


def row(model, label, level, ranks, s):
    t = s["timings"]
    return dict(model=model, discretisation=label, level=level, ranks=ranks,
                dofs=s["dofs"], cells=s["cells"],
                cg_iterations=s["solver"]["linear_iterations"],
                stiffness_N_per_mm=s["stiffness_N_per_mm"],
                t_mesh=t["mesh"], t_microstructure=t["microstructure"],
                t_embedding=t["embedding"], t_setup=t["setup"],
                t_assembly=t["assembly"], t_solve=t["solve"],
                t_total=t["total"], memory_MB=s["memory_MB"])


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(13, 5))
    keys = []
    for r in rows:
        if (r["model"], r["discretisation"], r["ranks"]) not in keys:
            keys.append((r["model"], r["discretisation"], r["ranks"]))
    for key in keys:
        rs = [r for r in rows if (r["model"], r["discretisation"],
                                  r["ranks"]) == key]
        style = "o-" if key[0] == "layers" else "s--"
        label = f"{key[0]}: {key[1]}" + (f" ({key[2]} ranks)"
                                         if int(key[2]) > 1 else "")
        err = [max(abs(float(r["relative_error"])), 1e-5) for r in rs]
        ax[0].loglog([float(r["t_total"]) for r in rs], err, style,
                     label=label)
        ax[1].loglog([int(r["dofs"]) for r in rs], err, style, label=label)
    for a, x in zip(ax, ["wall time [s]", "DoFs"]):
        a.axhline(0.01, color="k", lw=0.8, ls=":")
        a.axhline(0.003, color="k", lw=0.8, ls="-.")
        a.set_xlabel(x)
        a.set_ylabel("|k / k_converged - 1|")
        a.grid(True, which="both", alpha=0.3)
    ax[0].plot([1.4, 5.8], [0.01, 0.003], "r*", markersize=12,
               label="reference FE code, layers only (issue), 1 core")
    ax[0].legend(fontsize=7)
    fig.suptitle("Forearm indentation (bonded punch, linear): stiffness "
                 "error vs cost")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    os.makedirs(OUT, exist_ok=True)
    path = os.path.join(OUT, "forearm_speed_vs_error.csv")
    if "--plot-only" in sys.argv:
        with open(path) as f:
            plot(list(csv.DictReader(f)),
                 os.path.join(OUT, "forearm_speed_vs_error.png"))
        return
    rows = []
    with ssc_runner.scratch() as folder:
        for model, label, overrides, levels in CONFIGURATIONS:
            for level in levels:
                o = {**overrides,
                     "Mesh/Region of interest/Local refinements": str(level)}
                s = run(o, folder, "run")
                rows.append(row(model, label, level, 1, s))
                print(f"{model:15s} {label:32s} level {level}: "
                      f"{s['dofs']:8d} DoFs, k = "
                      f"{s['stiffness_N_per_mm']:.6f} N/mm, "
                      f"{s['solver']['linear_iterations']:4d} CG, "
                      f"{s['timings']['total']:6.1f} s", flush=True)
        converged = {}
        for model in ("layers", "microstructure"):
            ks = [r["stiffness_N_per_mm"] for r in rows
                  if r["model"] == model and
                  r["discretisation"] == REFERENCE[model]]
            converged[model], rate = richardson(ks)
            print(f"{model}: converged stiffness {converged[model]:.6f} N/mm "
                  f"(observed rate {rate:.2f})", flush=True)
        for r in rows:
            r["converged_N_per_mm"] = converged[r["model"]]
            r["relative_error"] = r["stiffness_N_per_mm"] / \
                converged[r["model"]] - 1
        # the cheapest single-core configuration within 1 % of each model,
        # then the same on 2 ranks
        for model in ("layers", "microstructure"):
            ok = [r for r in rows if r["model"] == model and
                  abs(r["relative_error"]) <= 0.01]
            if not ok:
                continue
            best = min(ok, key=lambda r: r["t_total"])
            config = [c for c in CONFIGURATIONS if c[0] == model and
                      c[1] == best["discretisation"]][0]
            o = {**config[2], "Mesh/Region of interest/Local refinements":
                 str(best["level"])}
            s = run(o, folder, "run2", ranks=2)
            r2 = row(model, best["discretisation"], best["level"], 2, s)
            r2["converged_N_per_mm"] = converged[model]
            r2["relative_error"] = r2["stiffness_N_per_mm"] / \
                converged[model] - 1
            rows.append(r2)
            print(f"cheapest within 1 % ({model}): {best['discretisation']} "
                  f"level {best['level']}, {best['dofs']} DoFs, error "
                  f"{100 * best['relative_error']:+.2f} %, "
                  f"{best['t_total']:.1f} s on 1 core, "
                  f"{r2['t_total']:.1f} s on 2 ranks", flush=True)

        # truncation: the scene's 80 mm patch (and a 60 mm one) against one
        # twice as large; the coarse cells grow outside the central 60 mm
        trunc = []
        for model, extra in (("layers", LAYERS), ("microstructure", ROI)):
            for small in (60, 80):
                ks = []
                for length in (small, 2 * small):
                    o = {**extra, **Q1E, **CS5,
                         "Mesh/Patch length x": str(length),
                         "Mesh/Patch length y": str(length),
                         "Mesh/Region of interest/Local refinements": "3"}
                    s = run(o, folder, "trunc")
                    ks.append(s["stiffness_N_per_mm"])
                    trunc.append(dict(model=model, patch_mm=length,
                                      dofs=s["dofs"],
                                      stiffness_N_per_mm=ks[-1]))
                print(f"truncation ({model}): {small} mm {ks[0]:.6f}, "
                      f"{2 * small} mm {ks[1]:.6f} N/mm, change "
                      f"{100 * (ks[0] / ks[1] - 1):+.3f} %", flush=True)
        with open(os.path.join(OUT, "forearm_truncation.csv"), "w",
                  newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(trunc[0].keys()))
            w.writeheader()
            w.writerows(trunc)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(OUT, "forearm_speed_vs_error.png"))


if __name__ == "__main__":
    main()
