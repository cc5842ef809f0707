#!/usr/bin/python3
"""Sensitivity of the growth scenes' surface to the sourced parameters
(issue 27): each parameter at the low and the high end of its literature
range, the others at their central values, for

- the cellulite scene (prm/buttock_cellulite.prm, 24 cm^3 of fat growth):
  Sa and Svm of the skin surface (ISO 25178 of the residual after the
  smooth trend; Svm as the clinical scans report it, Smalls et al. 2005:
  Sa 1.1 mm (0.3-2.1), Svm 2.8 mm (1.0-7.1) for women's thighs);
- the injection scenes (prm/cheek_injection_sat.prm and _dat.prm, 0.5 cm^3):
  the ratio of the SAT injection's Sq to the DAT injection's (the
  reference model shows orange peel after SAT and a smooth dome after DAT
  injection: the ratio should be well above 1).

    /usr/bin/python3 benchmarks/growth_sensitivity/growth_sensitivity.py
        [--jobs 2]

The central values of PARAMETERS are passed to both scenes (so the cheek
runs have 4 bands per cm^2 where prm/regions/cheek.prm has 3). The low end
of the skin modulus factor, 0.5, is the aged skin: aging should raise Sa.
Also the sourced corners most favourable to the clinical picture
(CELLULITE_CORNER, INJECTION_CORNER: the ends chosen from the
one-at-a-time results) and, beyond the sources, the bands contracted by 10
and 20 % (Embedded/Ligaments/Contraction). And the mechanism the study
found decisive, which no study measures: septa that grow with the fat
(Growth/Septum growth 0.5 and 1) instead of being stretched by it.

Runs every case once (one MPI rank each, --jobs at a time) and keeps its
summary in benchmarks/growth_sensitivity/results/runs/<case>/summary.json
(not in git; delete a folder to rerun; --kept-only reports the kept runs
and runs nothing); writes benchmarks/growth_sensitivity/results/
growth_sensitivity.csv and the tornado plot growth_sensitivity.png.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

ROOT = ssc_runner.ROOT
OUT = os.path.join(HERE, "results")
RUNS = os.path.join(OUT, "runs")
SCENES = {"buttock": "buttock_cellulite", "cheek_sat": "cheek_injection_sat",
          "cheek_dat": "cheek_injection_dat"}
LIG = "Embedded/Ligaments/"
SEPTA = "Embedded/Septa/"


def fat_nu(nu):
    overrides = {"Layer stack/SAT/Poisson's ratio": nu,
                 "Layer stack/DAT/Poisson's ratio": nu}
    if nu > 0.4995:
        # AMG-preconditioned CG needs about 10k iterations per Newton step
        # at nu = 0.4999 (the first buttock run was stopped at half the
        # growth after 20 minutes); the Cholesky factor is exact whatever
        # nu, on one rank as these runs are
        overrides["Elasticity/Linear solver/Preconditioner"] = "cholesky"
    return overrides


# (key, label, source, low, central, high, overrides(value)); the central
# values are those of the region files (prm/regions/buttock.prm, cheek.prm)
PARAMETERS = [
    ("tether_modulus", "tether modulus (MPa)",
     "0.1 (Herlin 2014, assumed) to 23 (Scarpa's fascia, tensile)",
     0.1, 1.5, 23, lambda v: {LIG + "Young's modulus": v}),
    ("tether_diameter", "tether diameter (mm)",
     "0.3 (Herlin 2014) to 2 (septa under depressions on MRI, Hexsel 2009)",
     0.3, 1.0, 2.0, lambda v: {LIG + "Diameter": v}),
    ("tether_density", "tether density (1/cm^2)", "estimate 1-8",
     1, 4, 8, lambda v: {"Microstructure/Ligaments/Density": v}),
    ("tether_angle", "tether angle from vertical (deg)",
     "oblique in 84 % (Whipple 2021); angle an estimate 0-60",
     0, 45, 60, lambda v: {"Microstructure/Ligaments/Inclination": v}),
    ("septa_modulus", "septa modulus (MPa)",
     "0.1 (Herlin 2014) to 23 (fascia)",
     0.1, 1.5, 23, lambda v: {SEPTA + "Young's modulus": v}),
    ("skin_modulus_factor", "skin modulus factor",
     "0.5 (aged) to 5 (in vivo skin moduli tens to hundreds of kPa)",
     0.5, 1, 5, lambda v: {"Layer stack/Skin modulus factor": v}),
    ("growth_spread", "lobule growth spread (ln)", "estimate 0-0.6",
     0, 0.3, 0.6, lambda v: {"Growth/Lobule growth spread": v}),
    ("fat_nu", "fat Poisson's ratio", "0.49 (Herlin 2014) to 0.4999",
     0.49, 0.499, 0.4999, fat_nu),
]


def central_overrides():
    overrides = {}
    for p in PARAMETERS:
        overrides.update(p[6](p[4]))
    return overrides


KEPT_ONLY = False


def run_case(case, scene, overrides):
    """Runs @p scene with @p overrides unless kept; returns its summary
    (None where the run failed, or was not kept with --kept-only)."""
    kept = os.path.join(RUNS, case, "summary.json")
    if not os.path.exists(kept) and KEPT_ONLY:
        return None
    if not os.path.exists(kept):
        work = tempfile.mkdtemp(prefix="growth_")
        result = ssc_runner.run(
            os.path.join(ROOT, "prm", scene + ".prm"),
            {"Run/Write fields": "false", **overrides}, work, case)
        print(f"{case}: exit status {result.returncode} after "
              f"{result.wall_s:.0f} s", flush=True)
        if not result.ok:
            print(result.stdout[-1500:], result.stderr[-1500:],
                  file=sys.stderr)
            ssc_runner.remove(work)
            return None
        # the summary, and the surface itself for the pictures
        ssc_runner.keep(result.folder, os.path.join(RUNS, case),
                        ["summary.json", "elevation.csv"])
        ssc_runner.remove(work)
    return ssc_runner.read_summary(os.path.join(RUNS, case))


def cases():
    """(case, scene, overrides, parameter key, end) of the whole study."""
    base = central_overrides()
    out = []
    for short, scene in SCENES.items():
        out.append((f"{short}_central", scene, base, "central", "central"))
        for key, _, _, low, _, high, overrides in PARAMETERS:
            for end, value in (("low", low), ("high", high)):
                out.append((f"{short}_{key}_{end}", scene,
                            {**base, **overrides(value)}, key, end))
    return out


# The sourced corners, chosen from the one-at-a-time results: each
# parameter at the end of its range that made the cellulite surface
# rougher (larger Sa; nu at 0.4999, since 0.49 was smoother than the
# central 0.499) and the SAT injection rougher (larger Sq; its DAT rows
# showed the tethers do not reach the deep fat); unnamed ones central.
CELLULITE_CORNER = {"tether_modulus": "high", "tether_diameter": "high",
                    "tether_density": "high", "tether_angle": "low",
                    "septa_modulus": "low", "skin_modulus_factor": "low",
                    "growth_spread": "high", "fat_nu": "high"}
INJECTION_CORNER = {"tether_modulus": "high", "tether_diameter": "high",
                    "tether_density": "high", "tether_angle": "high",
                    "septa_modulus": "low"}


def corner_overrides(ends):
    overrides = central_overrides()
    for key, _, _, low, central, high, override in PARAMETERS:
        if key in ends:
            overrides.update(override({"low": low, "central": central,
                                       "high": high}[ends[key]]))
    return overrides


def corner_cases():
    """The sourced corners most favourable to the clinical picture and,
    beyond the sources, the cellulite scene with the bands contracted
    (Embedded/Ligaments/Contraction, fibrotic shortening that no study
    measures)."""
    injection = corner_overrides(INJECTION_CORNER)
    out = [("buttock_corner", SCENES["buttock"],
            corner_overrides(CELLULITE_CORNER), "corner", "corner"),
           # the same with young skin: does aging raise Sa at the corner too?
           ("buttock_corner_young_skin", SCENES["buttock"],
            corner_overrides({**CELLULITE_CORNER,
                              "skin_modulus_factor": "central"}),
            "corner", "young skin"),
           ("cheek_sat_corner", SCENES["cheek_sat"], injection, "corner",
            "corner"),
           ("cheek_dat_corner", SCENES["cheek_dat"], injection, "corner",
            "corner")]
    for c in (0.1, 0.2):
        out.append((f"buttock_contraction_{c}", SCENES["buttock"],
                    {**central_overrides(), LIG + "Contraction": c},
                    "contraction", str(c)))
    for f in SEPTUM_GROWTH:
        for short, scene in SCENES.items():
            out.append((f"{short}_septum_growth_{f}", scene,
                        {**central_overrides(), "Growth/Septum growth": f},
                        "septum_growth", str(f)))
    # the injection ratio on a finer mesh (the scenes' 1.25 mm cells in
    # the centre against 0.9 mm)
    for short in ("cheek_sat", "cheek_dat"):
        for name, extra in (("central", {}),
                            ("septum_growth_1", {"Growth/Septum growth": 1})):
            out.append((f"{short}_{name}_h0.9", SCENES[short],
                        {**central_overrides(), **extra,
                         "Mesh/Cell size": 0.9}, "mesh", name))
    injection = corner_overrides(INJECTION_CORNER)
    for short in ("cheek_sat", "cheek_dat"):
        out.append((f"{short}_corner_h0.9", SCENES[short],
                    {**injection, "Mesh/Cell size": 0.9}, "mesh", "corner"))
    # and the cellulite's on 1.5 mm cells against 2 mm, central and at the
    # corner that reaches the clinical order
    out.append(("buttock_central_h1.5", SCENES["buttock"],
                {**central_overrides(), "Mesh/Cell size": 1.5}, "mesh",
                "central"))
    out.append(("buttock_corner_young_skin_h1.5", SCENES["buttock"],
                {**corner_overrides({**CELLULITE_CORNER,
                                     "skin_modulus_factor": "central"}),
                 "Mesh/Cell size": 1.5}, "mesh", "corner, young skin"))
    return out


# How far the septa grow with the fat (beyond the sources: 0 is the
# central case, the septa stretched by the growing lobules).
SEPTUM_GROWTH = (1, 0.5)


def metrics(summary):
    s = summary["surface"]
    return {"Sa_mm": s["Sa_mm"], "Sq_mm": s["Sq_mm"], "Svm_mm": s["Svm_mm"],
            "Sz_mm": s["Sz_mm"], "dimples": s["dimples"]["count"],
            "max_elevation_mm": summary["max_elevation_mm"],
            "wall_s": summary["timings"]["total"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--kept-only", action="store_true",
                        help="report and plot the kept runs, run nothing")
    parser.add_argument("--only", default="",
                        help="run only the cases whose name contains this "
                        "(the kept others are still reported)")
    args = parser.parse_args()
    global KEPT_ONLY
    KEPT_ONLY = args.kept_only
    rows = []
    todo = cases() + corner_cases()
    if args.only:
        todo = [c for c in todo
                if args.only in c[0]
                or os.path.exists(os.path.join(RUNS, c[0], "summary.json"))]
    with ThreadPoolExecutor(args.jobs) as pool:
        summaries = list(pool.map(lambda c: run_case(c[0], c[1], c[2]),
                                  todo))
    for (case, scene, _, key, end), summary in zip(todo, summaries):
        if summary is None:
            continue
        value = next((p[3] if end == "low" else p[5] for p in PARAMETERS
                      if p[0] == key), "")
        rows.append({"case": case, "scene": scene, "parameter": key,
                     "end": end, "value": value, **metrics(summary)})
    with open(os.path.join(OUT, "growth_sensitivity.csv"), "w",
              newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    report(rows)
    plot(rows)
    pictures()


def lookup(rows, case):
    return next((r for r in rows if r["case"] == case), None)


def ratio(rows, key_end):
    sat = lookup(rows, "cheek_sat_" + key_end)
    dat = lookup(rows, "cheek_dat_" + key_end)
    return sat["Sq_mm"] / dat["Sq_mm"] if sat and dat else float("nan")


def report(rows):
    c = lookup(rows, "buttock_central")
    print(f"cellulite, central: Sa {c['Sa_mm']:.3f} Svm {c['Svm_mm']:.3f} "
          f"Sz {c['Sz_mm']:.3f} mm, {c['dimples']} dimples "
          f"(measured Sa 1.1 (0.3-2.1), Svm 2.8 (1.0-7.1) mm)")
    aged = lookup(rows, "buttock_skin_modulus_factor_low")
    if aged:
        print(f"aged skin (modulus x 0.5): Sa {aged['Sa_mm']:.3f} mm "
              f"({aged['Sa_mm'] / c['Sa_mm'] - 1:+.0%})")
    print(f"injection, central: SAT/DAT Sq ratio {ratio(rows, 'central'):.2f}")
    rough = lookup(rows, "buttock_corner")
    if rough:
        print(f"cellulite at its sourced corner: Sa {rough['Sa_mm']:.3f} "
              f"Svm {rough['Svm_mm']:.3f} mm")
    print(f"injection at its sourced corner: SAT/DAT "
          f"{ratio(rows, 'corner'):.2f}")
    for case in ("buttock_corner_young_skin", "buttock_central_h1.5",
                 "buttock_corner_young_skin_h1.5"):
        r = lookup(rows, case)
        if r:
            print(f"{case}: Sa {r['Sa_mm']:.3f} Svm {r['Svm_mm']:.3f} mm")
    for key in ("central_h0.9", "septum_growth_1_h0.9", "corner_h0.9"):
        print(f"injection, {key}: SAT/DAT {ratio(rows, key):.2f}")
    for c in (0.1, 0.2):
        r = lookup(rows, f"buttock_contraction_{c}")
        if r:
            print(f"cellulite, bands contracted by {c:.0%}: Sa "
                  f"{r['Sa_mm']:.3f} Svm {r['Svm_mm']:.3f} mm, "
                  f"{r['dimples']} dimples")
    for f in SEPTUM_GROWTH:
        r = lookup(rows, f"buttock_septum_growth_{f}")
        if r:
            print(f"septa growing with the fat ({f}): cellulite Sa "
                  f"{r['Sa_mm']:.3f} Svm {r['Svm_mm']:.3f} mm; injection "
                  f"SAT/DAT {ratio(rows, f'septum_growth_{f}'):.2f}")
    print("| parameter | low | high | Sa low / high (mm) | Svm low / high "
          "(mm) | SAT/DAT low / high |")
    print("|---|---|---|---|---|---|")
    for key, label, _, low, _, high, _ in PARAMETERS:
        lo, hi = (lookup(rows, f"buttock_{key}_{e}") for e in ("low", "high"))
        if not (lo and hi):
            continue
        print(f"| {label} | {low} | {high} | {lo['Sa_mm']:.3f} / "
              f"{hi['Sa_mm']:.3f} | {lo['Svm_mm']:.3f} / {hi['Svm_mm']:.3f} "
              f"| {ratio(rows, key + '_low'):.2f} / "
              f"{ratio(rows, key + '_high'):.2f} |")


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = [("Sa (mm), cellulite", lambda e: lookup(
                  rows, "buttock_" + e)["Sa_mm"]),
              ("Svm (mm), cellulite", lambda e: lookup(
                  rows, "buttock_" + e)["Svm_mm"]),
              ("Sq SAT / Sq DAT, injection", lambda e: ratio(rows, e))]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.8), constrained_layout=True)
    for ax, (title, value) in zip(axes, panels):
        centre = value("central")
        spans = []
        for key, label, _, low, _, high, _ in PARAMETERS:
            try:
                lo, hi = value(key + "_low"), value(key + "_high")
            except TypeError:
                continue
            spans.append((abs(hi - lo), label, lo, hi, low, high))
        spans.sort()
        for k, (_, label, lo, hi, low, high) in enumerate(spans):
            ax.barh(k, lo - centre, left=centre, color="tab:blue")
            ax.barh(k, hi - centre, left=centre, color="tab:red")
        ax.set_yticks(range(len(spans)))
        ax.set_yticklabels([f"{s[1]}\n{s[4]} / {s[5]}" for s in spans],
                           fontsize=7)
        ax.axvline(centre, color="k", lw=0.8)
        ax.set_xscale("log")
        ax.set_title(f"{title}: central {centre:.3g}", fontsize=9)
    axes[0].axvspan(0.3, 2.1, color="tab:green", alpha=0.15,
                    label="measured range (Smalls 2005)")
    axes[1].axvspan(1.0, 7.1, color="tab:green", alpha=0.15)
    axes[2].axvline(2, color="tab:green", ls="--", label="ratio 2")
    axes[0].legend(fontsize=7, loc="lower right")
    fig.suptitle("Growth scenes: each parameter at the low (blue) and high "
                 "(red) end of its range, the others central", fontsize=10)
    path = os.path.join(OUT, "growth_sensitivity.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


# Elevation maps (scripts/plot_elevation.py) of kept runs whose surface is
# here (elevation.csv is not kept in git: rerun a case to draw it).
PICTURES = {
    "injection_surfaces.png": [
        ("cheek_dat_central_h0.9", "DAT, central"),
        ("cheek_sat_central_h0.9", "SAT, central"),
        ("cheek_sat_septum_growth_1_h0.9", "SAT, septa grow (f = 1)"),
        ("cheek_sat_corner_h0.9", "SAT, sourced corner")],
    "cellulite_surfaces.png": [
        ("buttock_septum_growth_1", "central, septa grow (f = 1)"),
        ("buttock_corner_young_skin", "sourced corner (severe.prm)"),
        ("buttock_corner", "sourced corner, aged skin"),
        ("buttock_corner_young_skin_h1.5", "sourced corner, 1.5 mm cells")]}


def pictures():
    for name, runs in PICTURES.items():
        present = [(case, title) for case, title in runs
                   if os.path.exists(os.path.join(RUNS, case,
                                                  "elevation.csv"))]
        if len(present) < 2:
            continue
        subprocess.run([sys.executable,
                        os.path.join(ROOT, "scripts", "plot_elevation.py"),
                        os.path.join(OUT, name)]
                       + [f"{os.path.join(RUNS, case)}={title}"
                          for case, title in present], check=True)


if __name__ == "__main__":
    main()
