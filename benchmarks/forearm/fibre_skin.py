#!/usr/bin/python3
"""What do fibre-reinforced and pre-tensioned skin change in the main scene?
prm/forearm_indentation.prm to 1.8 N as `./ssc.sh run` runs it (two MPI
ranks, CG with the V-cycle; no error estimate, no fields), with the skin

- isotropic (the shipped neo-Hookean, nu 0.49);
- isotropic and pre-tensioned: Prestretch 1.155, the plane tension
  h mu (s^2 - s^-4) = 6.2 N/m of the lower anterior forearm (Flynn et al.
  2011, Ann Biomed Eng 39:1935);
- fibre-reinforced (Gasser-Ogden-Holzapfel with the region's sourced
  fibres, Ni Annaidh et al. 2012) at nu 0.49999 (what the fibres need),
  Langer's lines across x (90 degrees, the forearm's if x runs along it)
  and along x (0 degrees).

The isotropic skin at nu 0.49999, which would separate the effect of nu
from that of the fibres, is not a variant: on the V-cycle its first
increments fail (CG does not converge in 1000 iterations, Newton not in
25) and the load is cut below 0.011 N (tried 2026-12-07).

Reads each run's summary and its surface profile along x (y = 0): the
depths, the stiffness (force / depth at 1.8 N) beside the only forearm
figure found (0.44-1.45 N/mm, Flynn et al. 2011, a glued micro-robot
probe, not a flat punch: an order of magnitude only), and the dimple's
half-width along x at 1.8 N (where the surface has risen to half the
centre's depth): the two line directions differ there if the skin is
anisotropic.

Writes benchmarks/forearm/results/fibre_skin.csv (one row per variant) and
fibre_skin.png (force against depth with the in vivo band; the profiles at
1.8 N).

    /usr/bin/python3 benchmarks/forearm/fibre_skin.py [--plot-only]
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402
from main_scene import SCENE  # noqa: E402
from main_scene import SHIPPED_RANKS as RANKS  # noqa: E402

CSV = os.path.join(HERE, "results", "fibre_skin.csv")
PROFILES = CSV.replace(".csv", "_profiles.csv")
COMMON = ["Run/Write fields=false", "Punch/Section=false",
          "Punch/Depth error estimate=none"]
FIBRES = ["Layer stack/skin/Material model=Gasser-Ogden-Holzapfel",
          "Layer stack/skin/Poisson's ratio=0.49999"]
VARIANTS = [
    ("isotropic skin (the scene)", []),
    ("isotropic skin, pre-tension 6.2 N/m", ["Layer stack/skin/Prestretch=1.155"]),
    ("fibres, lines across x", FIBRES),
    ("fibres, lines along x",
     FIBRES + ["Layer stack/skin/Gasser-Ogden-Holzapfel/Langer line angle=0"]),
]
# Flynn, Taberner, Nielsen 2011: maximum force over maximum displacement on
# the anterior forearm of 20 volunteers (prm/reference/)
IN_VIVO_N_PER_MM = (0.44, 1.45)


def half_width(x, uz):
    """The smallest x >= 0 where uz has risen to half its value at x = 0
    (linear between the samples)."""
    centre = min(range(len(x)), key=lambda k: abs(x[k]))
    half = 0.5 * uz[centre]
    for k in range(centre, len(x) - 1):
        if uz[k + 1] > half >= uz[k]:
            return x[k] + (half - uz[k]) * (x[k + 1] - x[k]) / (uz[k + 1] - uz[k])
    return float("nan")


def measure():
    rows, profiles = [], {}
    for label, overrides in VARIANTS:
        with ssc_runner.scratch() as tmp:
            result = ssc_runner.run(SCENE, COMMON + overrides, tmp, "run",
                                    ranks=RANKS, timeout=3600)
            if not result.ok:
                sys.exit(f"{label}: failed: {result.stderr[-500:]}")
            s = result.summary()
            profile = ssc_runner.read_table(os.path.join(tmp, "run"),
                                            "surface_profile.csv")
        x = [float(p["x_mm"]) for p in profile]
        uz = [float(p["uz_mm_at_F1.8"]) for p in profile]
        profiles[label] = (x, uz)
        row = dict(
            variant=label, dofs=s["dofs"],
            newton_iterations=s["solver"]["newton_iterations"],
            cg_iterations=s["solver"]["linear_iterations"],
            wall_s=round(s["timings"]["total"], 1),
            stiffness_N_per_mm=round(s["stiffness_N_per_mm"], 4),
            half_width_x_mm_at_1_8N=round(half_width(x, uz), 3),
            forces_N=" ".join(f"{f:.4f}" for f in s["force_N"]),
            depths_mm=" ".join(f"{d:.6f}" for d in s["depth_mm"]))
        print(row, flush=True)
        rows.append(row)
        ssc_runner.write_rows(CSV, rows)
    ssc_runner.write_rows(PROFILES, [
        dict(variant=label, x_mm=f"{xi:.4f}", uz_mm_at_1_8N=f"{u:.6f}")
        for label, (x, uz) in profiles.items() for xi, u in zip(x, uz)])


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    with open(PROFILES) as f:
        points = list(csv.DictReader(f))
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    largest = max(float(d) for r in rows for d in r["depths_mm"].split())
    band = [0., largest]
    left.fill_between(band, [d * IN_VIVO_N_PER_MM[0] for d in band],
                      [d * IN_VIVO_N_PER_MM[1] for d in band], color="0.85",
                      label="in vivo forearm, 0.44-1.45 N/mm\n"
                            "(Flynn et al. 2011, other probe)")
    for row in rows:
        forces = [0.] + [float(f) for f in row["forces_N"].split()]
        depths = [0.] + [float(d) for d in row["depths_mm"].split()]
        left.plot(depths, forces, "o-", ms=3,
                  label=f"{row['variant']}: {row['stiffness_N_per_mm']} N/mm")
        x = [float(p["x_mm"]) for p in points if p["variant"] == row["variant"]]
        uz = [float(p["uz_mm_at_1_8N"]) for p in points
              if p["variant"] == row["variant"]]
        centre = uz[min(range(len(x)), key=lambda k: abs(x[k]))]
        right.plot(x, [u / -centre for u in uz],
                   label=f"{row['variant']}: half-width "
                         f"{row['half_width_x_mm_at_1_8N']} mm")
    left.set_xlabel("depth (mm)")
    left.set_ylabel("force (N)")
    left.set_ylim(0., 1.9)
    left.set_title("force against depth", fontsize=10)
    left.legend(fontsize=7)
    right.set_xlabel("x (mm), y = 0")
    right.axhline(-0.5, color="0.6", lw=0.5)
    right.set_ylabel("uz / depth at 1.8 N")
    right.set_xlim(-15., 15.)
    right.set_title("the dimple along x, scaled by its depth", fontsize=10)
    right.legend(fontsize=7)
    fig.suptitle("main scene with fibre-reinforced or pre-tensioned skin "
                 "(2 ranks, CG with "
                 "the V-cycle)", fontsize=10)
    fig.tight_layout()
    fig.savefig(CSV.replace(".csv", ".png"), dpi=120)
    print("wrote", CSV.replace(".csv", ".png"))


if __name__ == "__main__":
    if sys.argv[1:] != ["--plot-only"]:
        measure()
    plot()
