#!/usr/bin/python3
"""Does the shipped main scene's answer depend on its load path, and what
are the modes along which its tangents turn indefinite?
prm/forearm_indentation.prm to 1.8 N as `./ssc.sh run` runs it (two MPI
ranks, CG with the V-cycle; no error estimate, no fields), in variants
that change the load increments only, and one that refines the skin
through its thickness:

- scene: the shipped path (4 first increments, growth by 1.5 after an
  increment of at most 4 Newton iterations);
- larger increments: growth after up to 6 iterations;
- fixed increments of 0.044 N: no growth, 8 first increments;
- skin 4 cells across instead of 2 (the o-grid around as shipped).

Every path converges each force to a residual of 1e-8 of the load, so
depths that differ between the first three are different equilibria at
the same force, not errors of the solve. Each run's log is read for the
points where the line search failed and trust-region steps took over,
and for where the unstable direction lives ("unstable direction" lines):
its centre and the share of |du| carried by its largest nodal entry (a
share near 1 is a mode of one node, the scale of the mesh; a physical
wrinkle spreads over several cells).

Writes benchmarks/forearm/results/scene_branches.csv (one row per
variant) and scene_branches.png (depth against the scene's path, and the
Newton iterations per force).

    /usr/bin/python3 benchmarks/forearm/scene_branches.py [--plot-only]
"""
import csv, os, re, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402
from main_scene import NO_PICTURES, SCENE  # noqa: E402
from main_scene import SHIPPED_RANKS as RANKS  # noqa: E402

CSV = os.path.join(HERE, "results", "scene_branches.csv")
COMMON = NO_PICTURES + ["Punch/Depth error estimate=none"]
VARIANTS = [
    ("scene", []),
    ("larger increments", ["Nonlinear solver/Easy iterations=6"]),
    ("fixed increments of 0.044 N", ["Nonlinear solver/Growth factor=1",
                                     "Nonlinear solver/Initial steps=8"]),
    ("skin 4 cells across", ["Layer stack/skin/Cells across=4"]),
]
UNSTABLE = re.compile(
    r"unstable direction: \|du\|\^2 centred at r = ([-\d.e+]+) \+- [-\d.e+]+ "
    r"mm, z = ([-\d.e+]+) .*largest [-\d.e+]+ \(([-\d.e+]+) of \|du\|\)")


def unstable_directions(log):
    """(r, z, share of the largest entry) of each unstable direction."""
    return [tuple(float(v) for v in m.groups())
            for m in UNSTABLE.finditer(log)]


def measure():
    rows = []
    for label, overrides in VARIANTS:
        s, log = ssc_runner.run_or_exit(label, SCENE, COMMON + overrides,
                                        ranks=RANKS, timeout=3600)
        solver = s["solver"]
        modes = unstable_directions(log)
        row = dict(
            variant=label, dofs=s["dofs"],
            newton_iterations=solver["newton_iterations"],
            newton_per_force=" ".join(
                str(n) for n in solver["newton_iterations_per_step"]),
            trust_region_phases=log.count("line search failed"),
            unstable_r_mm=" ".join(f"{r:.2f}" for r, _, _ in modes),
            unstable_z_mm=" ".join(f"{z:.2f}" for _, z, _ in modes),
            largest_node_share=" ".join(f"{w:.2f}" for _, _, w in modes),
            wall_s=round(s["timings"]["total"], 1),
            forces_N=" ".join(f"{f:.4f}" for f in s["force_N"]),
            depths_mm=" ".join(f"{d:.6f}" for d in s["depth_mm"]))
        print(row, flush=True)
        rows.append(row)
        ssc_runner.write_rows(CSV, rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    scene = next(r for r in rows if r["variant"] == "scene")
    forces = [float(f) for f in scene["forces_N"].split()]
    reference = [float(d) for d in scene["depths_mm"].split()]
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    width = 0.8 / len(rows)
    for k, row in enumerate(rows):
        depths = [float(d) for d in row["depths_mm"].split()]
        left.plot(forces, [100. * (d / d0 - 1.)
                           for d, d0 in zip(depths, reference)],
                  "o-", label=f"{row['variant']} ({row['dofs']} DoFs)")
        newton = [int(n) for n in row["newton_per_force"].split()]
        right.bar([i + (k - (len(rows) - 1) / 2) * width
                   for i in range(len(newton))], newton, width=width,
                  label=f"{row['variant']}: {row['newton_iterations']}")
    left.axhline(0., color="k", lw=0.5)
    left.set_xlabel("force (N)")
    left.set_ylabel("depth against the scene's path (%)")
    left.set_title("the same force, another equilibrium", fontsize=10)
    left.legend(fontsize=7)
    right.set_xticks(range(len(forces)))
    right.set_xticklabels([f"{f:g}" for f in forces])
    right.set_xlabel("force (N)")
    right.set_ylabel("Newton iterations to this force")
    right.set_title("where the iterations go", fontsize=10)
    right.legend(fontsize=7)
    fig.suptitle("main scene, 2 ranks, CG with the V-cycle", fontsize=10)
    fig.tight_layout()
    fig.savefig(CSV.replace(".csv", ".png"), dpi=120)
    print("wrote", CSV.replace(".csv", ".png"))


if __name__ == "__main__":
    if sys.argv[1:] != ["--plot-only"]:
        measure()
    plot()
