#!/usr/bin/python3
"""The closure scene (prm/forearm_ellipse_closure.prm): a 12 x 4 mm surgical
ellipse excised from the pre-tensioned skin of the forearm, once along x
and once along y, and closed by five sutures. How much force the sutures
carry, how high the dog ears rise, how much that depends on the mesh, the
pre-tension and the skin's law, and whether the ellipse along Langer's lines
closes with less force than the one across them.

Variants (one ssc run each, one MPI rank, Cholesky; no fields):

- the scene as shipped (isotropic neo-Hookean skin, E 0.02 MPa, nu 0.49,
  prestretch 1.2, 1 mm cells; 0.5 mm cells did not get through the
  closure's indefinite Newton iterations in reasonable time);
- the pre-tension's sourced range: prestretch 1.155 (6.2
  N/m, Flynn et al. 2011's lower anterior forearm) and 1.222 (a freed disc
  shrinking by 33 %, Deroy et al. 2017);
- the fibre-reinforced skin (Gasser-Ogden-Holzapfel, Ni Annaidh et al.
  2012's fibres, nu 0.49999, Langer's lines along y) with the fibres
  recruited at the prestretch (slack in vivo, engaged by the closure): the
  ellipse along x lies across the lines, the one along y along them. On
  the scene itself (prestretch 1.2) its Newton iterations crawl through
  trust-region steps (a quarter of the first ellipse's closure in 12
  minutes, stopped 2026-12-07), so it runs on the small closure test's
  model (tests/closure_small.prm: a 6 x 2 mm ellipse on a 20 mm patch,
  prestretch 1.1, fibres recruited at 1.1, three sutures 1.5 mm apart).

Writes benchmarks/forearm/results/closure.csv (one row per run) and
closure.png.

    /usr/bin/python3 benchmarks/forearm/closure.py [--plot-only]
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402
from incision import common_columns, run_variant  # noqa: E402

SCENE = os.path.join(ROOT, "prm", "forearm_ellipse_closure.prm")
SMALL = os.path.join(ROOT, "tests", "closure_small.prm")
CSV = os.path.join(HERE, "results", "closure.csv")
FIBRES = ["Run/Test mode=false",
          "Layer stack/skin/Material model=Gasser-Ogden-Holzapfel",
          "Layer stack/skin/Poisson's ratio=0.49999",
          "Layer stack/skin/Gasser-Ogden-Holzapfel/"
          "Fibre recruitment stretch=1.1",
          # the stiff fibres' round-off floor of the residual
          "Nonlinear solver/Absolute tolerance=1e-9"]
# (model, label, global refinements, overrides)
VARIANTS = [
    (SCENE, "isotropic, s 1.2 (scene)", 0, []),
    (SCENE, "isotropic, s 1.155", 0, ["Layer stack/skin/Prestretch=1.155"]),
    (SCENE, "isotropic, s 1.222", 0, ["Layer stack/skin/Prestretch=1.222"]),
    (SMALL, "small test, isotropic, s 1.1", 0, ["Run/Test mode=false"]),
    (SMALL, "small test, fibres recruited at s 1.1", 0, FIBRES),
]


def measure(variants):
    rows = []
    for prm, label, refinements, overrides in variants:
        s, wall = run_variant(prm, label, refinements, overrides)
        row = {"model": os.path.basename(prm), **common_columns(
            label, refinements, s)}
        for axis in ("x", "y"):
            wound = s["wound"][f"ellipse_along_{axis}"]
            closed = s["closure"][f"ellipse_along_{axis}"]
            row.update({
                f"opened_area_change_{axis}_pct": wound["area_change_pct"],
                f"relative_to_lines_{axis}":
                    closed["relative_to_langer_lines"] or "",
                f"force_per_suture_{axis}_N": closed["force_per_suture_N"],
                f"max_suture_force_{axis}_N": closed["max_suture_force_N"],
                f"max_skin_stress_{axis}_kPa": closed["max_skin_stress_kPa"],
                f"dog_ear_height_{axis}_mm": closed["dog_ear_height_mm"],
                f"residual_gap_{axis}_mm": closed["residual_gap_mm"],
            })
        ratio = s["closure"].get("force_ratio_across_to_along",
                                 s["closure"].get("force_ratio_x_to_y"))
        row["force_ratio"] = ratio
        row["force_ratio_kind"] = ("across_to_along"
                                   if "force_ratio_across_to_along"
                                   in s["closure"] else "x_to_y")
        row["newton_iterations"] = s["solver"]["newton_iterations"]
        row["wall_s"] = wall
        rows.append(row)
        print(row)
        # after each run: a stopped benchmark keeps what it measured
        ssc_runner.write_rows(CSV, rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2),
                                      constrained_layout=True)
    labels = [f"{r['variant']}\n{'0.5' if r['refinements'] == '1' else '1'}"
              " mm cells" for r in rows]
    positions = range(len(rows))
    for ax, key, unit, title in (
            (left, "force_per_suture", "N", "mean force per suture, closed"),
            (right, "dog_ear_height", "mm", "dog-ear height, closed")):
        for offset, axis in ((-0.2, "x"), (0.2, "y")):
            ax.barh([p + offset for p in positions],
                    [float(r[f"{key}_{axis}_{unit}"]) for r in rows], 0.4,
                    label=f"ellipse along {axis}")
        ax.set_yticks(list(positions))
        ax.set_yticklabels(labels if ax is left else [], fontsize=7)
        ax.set_xscale("log")
        ax.set_xlabel(f"{title} ({unit}, log scale)")
        ax.grid(alpha=0.3, axis="x")
        ax.legend(fontsize=8)
    fig.suptitle("closure of a 12 x 4 mm ellipse on the forearm by five "
                 "sutures, and of the small test's 6 x 2 mm ellipse by three"
                 "\n(fibre skin: Langer's lines along y, so the ellipse along "
                 "x lies across them)", fontsize=9)
    fig.savefig(CSV.replace(".csv", ".png"), dpi=130)
    print("wrote", os.path.relpath(CSV.replace(".csv", ".png"), ROOT))


if __name__ == "__main__":
    if "--plot-only" not in sys.argv:
        measure(VARIANTS)
    plot()
