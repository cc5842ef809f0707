#!/usr/bin/python3
"""The incision scene (prm/forearm_incision.prm): how wide a 10 mm cut of
the forearm's skin opens, how converged that is, what decides it, and
whether it opens more across Langer's lines than along them.

Variants (one ssc run each, one MPI rank: the scene factorises its tangents
with Cholesky; no fields):

- the scene as shipped (isotropic neo-Hookean skin, E 0.02 MPa, nu 0.49,
  prestretch 1.2, 0.5 mm cells along the cut) and on the mesh with one
  refinement fewer (1 mm): the gap's discretisation error, estimated by
  Richardson extrapolation with the first order that tests/incision_plate
  measured for the same cut against Griffith's crack;
- the pre-tension's sourced range on the 1 mm mesh: prestretch 1.155 (6.2
  N/m, lower anterior forearm, Flynn et al. 2011), 1.2 (the scene), 1.222
  (a freed disc shrinking by 33 % in area, Deroy et al. 2017, dog skin);
- the cut through the superficial fat as well (Deepest layer cut = SAT);
- the fibre-reinforced skin (Gasser-Ogden-Holzapfel, Ni Annaidh et al.
  2012's fibres, nu 0.49999, Langer's lines along y) with the prestretch
  that gives the same order of skin tension (1.00002: 6-8 N/m), on the 1
  mm mesh: the cut along x runs across the lines, the cut along y along
  them.

The excision scene (prm/forearm_excision.prm: a disc of 8 mm excised
through the dermis) on both meshes and with the fibre-reinforced skin:
the wound's area change, aspect ratio and orientation
(results/excision.csv).

Writes benchmarks/forearm/results/incision.csv (one row per run) and
incision.png (gap against the skin tension; the variants' gaps).

    /usr/bin/python3 benchmarks/forearm/incision.py [--plot-only |
                                                     --excision-only]
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

SCENE = os.path.join(ROOT, "prm", "forearm_incision.prm")
CSV = os.path.join(HERE, "results", "incision.csv")
COMMON = ["Run/Write fields=false"]
COARSE = ["Mesh/Global refinements=0"]
FIBRES = ["Layer stack/skin/Material model=Gasser-Ogden-Holzapfel",
          "Layer stack/skin/Poisson's ratio=0.49999",
          "Layer stack/skin/Prestretch=1.00002",
          # the stiff fibres' round-off floor of the residual is about
          # 1e-11 N: the default absolute tolerance is below it
          "Nonlinear solver/Absolute tolerance=1e-9"]
VARIANTS = [
    ("isotropic, s 1.2 (scene)", 1, []),
    ("isotropic, s 1.2 (scene)", 0, []),
    ("isotropic, s 1.155", 0, ["Layer stack/skin/Prestretch=1.155"]),
    ("isotropic, s 1.222", 0, ["Layer stack/skin/Prestretch=1.222"]),
    ("isotropic, s 1.2, cut into SAT", 0,
     ["Incision/Deepest layer cut=SAT"]),
    # on the 0.5 mm mesh it did not finish in 10 minutes (stopped
    # 2026-12-07): the stiff fibres' residual floor
    ("fibres, s 1.00002", 0, FIBRES),
]


EXCISION = os.path.join(ROOT, "prm", "forearm_excision.prm")
EXCISION_CSV = os.path.join(HERE, "results", "excision.csv")
EXCISION_VARIANTS = [
    ("isotropic, s 1.2 (scene)", 1, []),
    ("isotropic, s 1.2 (scene)", 0, []),
    ("fibres, s 1.00002", 0, FIBRES),
]


def run_variant(prm, label, refinements, overrides):
    """One run of prm with the overrides on the mesh with refinements:
    its summary and wall time (stops the script if it fails)."""
    settings = COMMON + overrides + [f"Mesh/Global refinements={refinements}"]
    with ssc_runner.scratch() as tmp:
        result = ssc_runner.run(prm, settings, tmp, "run", ranks=None,
                                timeout=3600)
        if not result.ok:
            sys.exit(f"{label}: failed: {result.stderr[-500:]}")
        return result.summary(), round(result.wall_s, 1)


def common_columns(label, refinements, summary):
    """The first columns of every row: the variant, its mesh and the skin
    tension far from the cut."""
    tension = summary["wound"]["skin_tension_N_per_m"]
    return {"variant": label, "refinements": refinements,
            "dofs": summary["dofs"],
            "skin_tension_x_N_per_m": tension["x"],
            "skin_tension_y_N_per_m": tension["y"]}


def measure_excision():
    rows = []
    for label, refinements, overrides in EXCISION_VARIANTS:
        s, wall = run_variant(EXCISION, label, refinements, overrides)
        wound = s["wound"]
        rows.append({
            **common_columns(label, refinements, s),
            "wound_area_change_pct": wound["area_change_pct"],
            "wound_aspect_ratio": wound["aspect_ratio"],
            "wound_orientation_deg": wound["orientation_deg"],
            "wound_long_axis_mm": wound["length_mm"],
            "wound_short_axis_mm": wound["gap_mm"],
            "disc_area_change_pct": s["disc"]["area_change_pct"],
            "newton_iterations": s["solver"]["newton_iterations"],
            "wall_s": wall,
        })
        print(rows[-1])
    ssc_runner.write_rows(EXCISION_CSV, rows)


def measure():
    rows = []
    for label, refinements, overrides in VARIANTS:
        s, wall = run_variant(SCENE, label, refinements, overrides)
        x, y = s["wound"]["cut_along_x"], s["wound"]["cut_along_y"]
        rows.append({
            **common_columns(label, refinements, s),
            "gap_cut_x_mm": x["gap_mm"],
            "gap_cut_y_mm": y["gap_mm"],
            "area_cut_x_mm2": x["area_mm2"],
            "area_cut_y_mm2": y["area_mm2"],
            "aspect_cut_x": x["aspect_ratio"],
            "aspect_cut_y": y["aspect_ratio"],
            "cut_x_relative_to_lines": x["relative_to_langer_lines"] or "",
            "newton_iterations": s["solver"]["newton_iterations"],
            "wall_s": wall,
        })
        print(rows[-1])
    ssc_runner.write_rows(CSV, rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(CSV, newline="") as f:
        rows = list(csv.DictReader(f))
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4),
                                      constrained_layout=True)
    iso = [r for r in rows if r["variant"].startswith("isotropic, s 1.")
           and "SAT" not in r["variant"] and r["refinements"] == "0"]
    iso.sort(key=lambda r: float(r["skin_tension_x_N_per_m"]))
    left.plot([float(r["skin_tension_x_N_per_m"]) for r in iso],
              [float(r["gap_cut_x_mm"]) for r in iso], "o-",
              label="isotropic skin, 1 mm cells")
    left.axvspan(6.2, 11.4, color="0.85",
                 label="in vivo tension, forearm (Flynn 2011)")
    left.set_xlabel("skin tension far from the cut (N/m)")
    left.set_ylabel("gap of a 10 mm incision (mm)")
    left.grid(alpha=0.3)
    left.legend(fontsize=8)
    labels = [f"{r['variant']}\n{'0.5' if r['refinements'] == '1' else '1'}"
              " mm cells" for r in rows]
    positions = range(len(rows))
    right.barh([p - 0.2 for p in positions],
               [float(r["gap_cut_x_mm"]) for r in rows], 0.4,
               label="cut along x")
    right.barh([p + 0.2 for p in positions],
               [float(r["gap_cut_y_mm"]) for r in rows], 0.4,
               label="cut along y")
    right.set_yticks(list(positions))
    right.set_yticklabels(labels, fontsize=7)
    right.set_xscale("log")
    right.set_xlabel("gap (mm, log scale)")
    right.legend(fontsize=8)
    right.set_title("fibre skin: Langer's lines along y, so the cut along x "
                    "runs across them", fontsize=8)
    fig.savefig(CSV.replace(".csv", ".png"), dpi=130)
    print("wrote", os.path.relpath(CSV.replace(".csv", ".png"), ROOT))


if __name__ == "__main__":
    if "--excision-only" in sys.argv:
        measure_excision()
    elif "--plot-only" not in sys.argv:
        measure()
        measure_excision()
    plot()
