#!/usr/bin/python3
"""The finite-strain forearm indentation (prm/forearm_indentation.prm, the
main scene): how far its depths are mesh-converged, how much the lobule
realisation moves them, and the reference model's set-up reproduced.

    /usr/bin/python3 benchmarks/forearm/forearm_finite_strain.py convergence
    /usr/bin/python3 benchmarks/forearm/forearm_finite_strain.py seeds [N]
    /usr/bin/python3 benchmarks/forearm/forearm_finite_strain.py herlin
    /usr/bin/python3 benchmarks/forearm/forearm_finite_strain.py roi
    /usr/bin/python3 benchmarks/forearm/forearm_finite_strain.py poisson
    /usr/bin/python3 benchmarks/forearm/forearm_finite_strain.py friction
    /usr/bin/python3 benchmarks/forearm/forearm_finite_strain.py plot

convergence: the scene (the real indenter: flat face bonded, rounding in
frictionless contact) at every force, Q1 with the cell's mean dilatation
(Q1-P0) on o-grids of 8, 12 and 16 cells around (the scene's is 12 around,
0.2 mm) and Q2 u-p (Q2-P1, Formulation = mixed, the septa with the default
2 Gauss points per direction) on the 8-around o-grid, and the scene with a
frictionless face; lobule seed 1 throughout. The depth uncertainty of the
scene's discretisation at each force is its distance from the finest run
that reached that force plus that run's distance from the next finest (the
reference's own error, bounded by how much the two finest discretisations
disagree); where the finest run did not reach a force, the largest
relative uncertainty of the forces it reached times the scene's depth
(extrapolated, and printed as such). Until 2026-12-06 the scene's prm
held these as typed error bars (Punch/Depth uncertainty); the scene now
computes its own (Punch/Depth error estimate, depth_error_effectivity.py).
Every study here is made on the scene's discretisation as it was then
(BASE: 12 around, 0.2 mm, grading 1.4, no refinement level, Cholesky).

seeds: the scene with lobule seeds 1..N (default 10): mean and standard
deviation of the depth at each force and of the stiffness.

herlin: prm/forearm_indentation_herlin2014.prm (the reference model's
moduli on the scene's discretisation) and the reference model's own
set-up: a 2 mm grid of Q1 displacement elements (no refinement), every
layer corotational, nu = 0.49, its moduli.

roi: one lobule and ligament realisation (seed 1, drawn in the 60 x 60 mm
square about the punch: Realisation half width = 30) cut at region radii
5-30 mm, and the layers alone, the septa alone and the ligaments alone in
the 30 mm region: depth and stiffness against the 30 mm region, and the
wall time.

poisson: nu = 0.4999 in the fat (SAT, DAT; skin, fascia and muscle keep
0.49) against the scene's nu = 0.49, on the scene's discretisation and on
Q2-P1 (8 around, to 1.0 N: the 0.49 run crawls beyond 1.5 N); and in
every layer on the scene's discretisation.

friction: Coulomb friction on the flat face (Contact = friction, mu 0.2,
0.5 and 0.8, the in vivo range of dry skin on steel or glass) beside the
bonded face (the scene) and the frictionless one, on the scene's
discretisation; the rounding stays frictionless.

Each run is kept in benchmarks/forearm/results/runs/<case>/ (summary and
force-displacement table only; not in git) and not repeated; delete a
folder to rerun. Writes benchmarks/forearm/results/forearm_convergence.csv,
forearm_seeds.csv, forearm_herlin.csv, forearm_roi.csv, forearm_poisson.csv,
forearm_friction.csv and forearm_convergence.png. One MPI rank (the scene
factorises its tangents), its cell loops on every core unless
DEAL_II_NUM_THREADS says otherwise (the kept runs: one thread; poisson and
friction were run with DEAL_II_NUM_THREADS=1 beside other jobs).
"""
import csv, os, re, statistics, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

ROOT = ssc_runner.ROOT
SCENE = os.path.join(ROOT, "prm", "forearm_indentation.prm")
HERLIN = os.path.join(ROOT, "prm", "forearm_indentation_herlin2014.prm")
OUT = os.path.join(HERE, "results")
RUNS = os.path.join(OUT, "runs")
RANKS = 1
BASE = {"Run/Write fields": "false", "Punch/Section": "false",
        "Punch/Profile length": "0",
        # the scene's discretisation until 2026-12-06, which the studies
        # here were made on (the convergence cases override the o-grid)
        "Mesh/O-grid/Cells around": "12", "Mesh/O-grid/Edge cell size": "0.2",
        "Mesh/O-grid/Radial grading": "1.4", "Mesh/Global refinements": "0",
        "Elasticity/Linear solver/Preconditioner": "cholesky",
        "Punch/Depth error estimate": "none"}
Q1 = {"Elasticity/Degree": "1", "Elasticity/Formulation": "mean dilatation"}
Q2P1 = {"Elasticity/Degree": "2", "Elasticity/Formulation": "mixed",
        "Embedded/Septa/Quadrature points": "2"}


def ogrid(around, edge, grading):
    """The o-grid's cells around, radial size at the circle, grading."""
    return {"Mesh/O-grid/Cells around": str(around),
            "Mesh/O-grid/Edge cell size": str(edge),
            "Mesh/O-grid/Radial grading": str(grading)}


# (contact, discretisation, mesh label, overrides), coarse to fine
CONVERGENCE = [
    ("bonded", "Q1-P0", "n8 h0.3", {**Q1, **ogrid(8, 0.3, 1.6)}),
    ("bonded", "Q1-P0", "n12 h0.2", {**Q1, **ogrid(12, 0.2, 1.4)}),
    ("bonded", "Q1-P0", "n12 h0.15", {**Q1, **ogrid(12, 0.15, 1.3)}),
    ("bonded", "Q1-P0", "n16 h0.15", {**Q1, **ogrid(16, 0.15, 1.3)}),
    ("bonded", "Q2-P1", "n8 h0.3", {**Q2P1, **ogrid(8, 0.3, 1.6)}),
    # a frictionless face (the rounding in contact as before): no Q2
    # reference (Q2 with a frictionless face crawled in the hard cases,
    # benchmarks/finite_strain_solver/README.md)
    ("frictionless", "Q1-P0", "n12 h0.2", {**Q1, **ogrid(12, 0.2, 1.4)}),
]
# the scene's discretisation
SCENE_CASE = ("Q1-P0", "n12 h0.2")
# the reference model's set-up (Herlin et al. 2014): a regular 2 mm grid of
# hexahedra (no mesh line on the punch's circle), Q1 displacement,
# corotational, nu 0.49, its moduli; the rounded punch edge in contact as
# in the scene
HERLIN_SETUP = {"Elasticity/Degree": "1",
                "Elasticity/Formulation": "displacement",
                "Mesh/Layout": "box", "Punch/Tied region": "whole face",
                "Mesh/Cell size": "2", "Mesh/Core half width": "30",
                "Mesh/Grading ratio": "1.5",
                "Mesh/Fitted circle radius": "0",
                # as when it was first measured (2026-12-04)
                "Punch/Contact penalty": "100",
                "Embedded/Septa/Quadrature points": "2"}
for layer in ["skin", "SAT", "SM", "DAT", "deep"]:
    HERLIN_SETUP[f"Layer stack/{layer}/Material model"] = "corotational"


def run(prm, name, overrides):
    """Runs ssc once (or reads the kept result): summary and steps."""
    folder = os.path.join(RUNS, name)
    summary_file = os.path.join(folder, "summary.json")
    if not os.path.exists(summary_file) and \
            not os.path.exists(os.path.join(folder, "log.txt")):
        with ssc_runner.scratch() as tmp:
            print("running", name, flush=True)
            # through mpirun with its default binding of the ranks to cores
            # (bind=True), as the kept runs were made
            result = ssc_runner.run(prm, {**BASE, **overrides}, tmp, "run",
                                    ranks=RANKS, bind=True)
            os.makedirs(folder, exist_ok=True)
            if result.returncode != 0:
                # kept: the load steps it finished still count
                with open(os.path.join(folder, "log.txt"), "w") as f:
                    f.write(result.stdout + result.stderr)
                print(f"  {name} failed (exit {result.returncode}); "
                      f"log in {folder}", flush=True)
                return stopped_run(folder)
            ssc_runner.keep(result.folder, folder,
                            ["summary.json", "force_displacement.csv"])
    if not os.path.exists(summary_file):
        return stopped_run(folder)
    return ssc_runner.read_summary(folder)


def stopped_run(folder):
    """What a run that stopped short (failed, or stopped by hand in a
    crawl; its ssc output kept as log.txt) reached: the DoFs and the load
    steps it finished, from its progress lines (None if it reached none)."""
    log = os.path.join(folder, "log.txt")
    if not os.path.exists(log):
        return None
    dofs, forces, depths, newton = None, [], [], 0
    step = re.compile(r"Load step \d+ of \d+: force ([-\d.e+]+) N, depth "
                      r"([-\d.e+]+) mm \(.*?(\d+) Newton iterations")
    for line in open(log):
        if line.startswith("Degrees of freedom:"):
            dofs = int(line.split(":")[1].split()[0])
        m = step.search(line)
        if m:
            forces.append(float(m.group(1)))
            depths.append(float(m.group(2)))
            newton += int(m.group(3))
    if not forces:
        return None
    return {"dofs": dofs, "force_N": forces, "depth_mm": depths,
            "timings": {"total": None}, "solver": {"newton_iterations": newton},
            "stopped_short": True}


def depths_at(summary, forces):
    """The run's depth at each scene force (None where it did not get)."""
    if summary is None:
        return [None] * len(forces)
    reached = dict(zip([round(f, 6) for f in summary["force_N"]],
                       summary["depth_mm"]))
    return [reached.get(round(f, 6)) for f in forces]


def scene_list(name):
    """The list of numbers the scene's prm sets for Punch/@p name."""
    for line in open(SCENE):
        if line.strip().startswith(f"set {name} "):
            return [float(v) for v in line.split("=")[1].split(",")]
    raise RuntimeError(f"no Punch/{name} in " + SCENE)


def scene_forces():
    return scene_list("Forces")


def result_columns(summary, forces):
    """The columns every table shares: wall time and the depth per force
    (empty where the run failed or stopped short)."""
    columns = {"wall_time_s": round(summary["timings"]["total"], 1)
               if summary and summary["timings"]["total"] else ""}
    for f, d in zip(forces, depths_at(summary, forces)):
        columns[f"depth_mm_at_{f}N"] = "" if d is None else d
    return columns


def solver_columns(summary):
    """The stiffness and the Newton iterations of a run (empty where it
    failed; no stiffness where it stopped short)."""
    return {"stiffness_N_per_mm": summary.get("stiffness_N_per_mm", "")
            if summary else "",
            "newton_iterations": summary["solver"]["newton_iterations"]
            if summary else ""}


def write_csv(path, fields, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    print("wrote", os.path.relpath(path, ROOT))


def convergence():
    forces = scene_forces()
    rows = []
    for contact, label, mesh, overrides in CONVERGENCE:
        name = f"{contact}_{label}_{mesh.replace(' ', '_')}"
        s = run(SCENE, name, {**overrides, "Punch/Contact": contact})
        rows.append({"contact": contact, "discretisation": label,
                     "mesh": mesh, "dofs": s["dofs"] if s else "",
                     "newton_iterations": s["solver"]["newton_iterations"]
                     if s and "newton_iterations" in s["solver"] else "",
                     **result_columns(s, forces)})
    fields = ["contact", "discretisation", "mesh", "dofs", "wall_time_s",
              "newton_iterations"] + [f"depth_mm_at_{f}N" for f in forces]
    write_csv(os.path.join(OUT, "forearm_convergence.csv"), fields, rows)
    for contact in sorted({c[0] for c in CONVERGENCE}):
        uncertainty(contact, forces,
                    [r for r in rows if r["contact"] == contact])


def uncertainty(contact, forces, rows):
    """Prints the scene discretisation's depth uncertainty per force: the
    finest run is the Q2-P1 one where there is one (most accurate per DoF),
    the next finest the Q1-P0 run with the most DoFs."""
    scene = [r for r in rows if (r["discretisation"], r["mesh"]) ==
             SCENE_CASE][0]
    ranked = sorted([r for r in rows if r["dofs"] != ""],
                    key=lambda r: (r["discretisation"] == "Q2-P1",
                                   r["dofs"]), reverse=True)
    values = []
    for f in forces:
        key = f"depth_mm_at_{f}N"
        reached = [r for r in ranked if r[key] != ""]
        if scene[key] == "" or len(reached) < 2 or reached[0] is scene or \
                reached[0] is not ranked[0]:
            values.append(None)
            continue
        best, second = reached[0], reached[1]
        values.append(abs(scene[key] - best[key]) +
                      abs(best[key] - second[key]))
        print(f"{contact} {f} N: scene {scene[key]:.3f} mm, finest "
              f"{best['discretisation']} {best['mesh']} {best[key]:.3f} mm, "
              f"next {second['discretisation']} {second['mesh']} "
              f"{second[key]:.3f} mm -> +-{values[-1]:.3f} mm")
    # where the finest run did not reach a force, the largest relative
    # uncertainty of the forces it reached, times the scene's depth
    # (extrapolated, and said so)
    relative = [v / scene[f"depth_mm_at_{f}N"]
                for f, v in zip(forces, values) if v is not None]
    for i, f in enumerate(forces):
        depth = scene[f"depth_mm_at_{f}N"]
        if values[i] is None and relative and depth != "":
            values[i] = max(relative) * depth
            print(f"{contact} {f} N: scene {depth:.3f} mm, the finest run "
                  f"did not reach it -> +-{values[i]:.3f} mm "
                  f"(extrapolated: {max(relative):.1%} of the depth)")
    print(f"{contact}: Depth uncertainty = " +
          ", ".join("?" if v is None else f"{v:.2f}" for v in values))
    return values


def seeds(n):
    forces = scene_forces()
    rows = []
    for seed in range(1, n + 1):
        s = run(SCENE, f"seed{seed}", {"Microstructure/Seed": str(seed)})
        rows.append({"seed": seed,
                     "stiffness_N_per_mm": s["stiffness_N_per_mm"] if s
                     else "", **result_columns(s, forces)})
    fields = ["seed", "stiffness_N_per_mm", "wall_time_s"] + \
        [f"depth_mm_at_{f}N" for f in forces]
    for stat, fn in [("mean", statistics.mean), ("std", statistics.stdev)]:
        row = {"seed": stat}
        for key in fields[1:]:
            values = [r[key] for r in rows if r[key] != ""]
            row[key] = fn(values) if len(values) > 1 else ""
        rows.append(row)
    write_csv(os.path.join(OUT, "forearm_seeds.csv"), fields, rows)
    for r in rows[-2:]:
        print(r["seed"], ", ".join(f"{k}: {v:.4g}" for k, v in r.items()
                                   if k != "seed" and v != ""))


def herlin():
    forces = scene_forces()
    rows = []
    for name, prm, overrides in [
            ("herlin2014_scene", HERLIN, {}),
            ("herlin2014_setup", HERLIN, HERLIN_SETUP),
            ("in_vivo_setup", SCENE, HERLIN_SETUP)]:
        s = run(prm, name, overrides)
        rows.append({"case": name, "dofs": s["dofs"] if s else "",
                     **result_columns(s, forces)})
    fields = ["case", "dofs", "wall_time_s"] + \
        [f"depth_mm_at_{f}N" for f in forces]
    write_csv(os.path.join(OUT, "forearm_herlin.csv"), fields, rows)


# region-of-interest study: one realisation (drawn in the 60 x 60 mm
# square about the punch) cut at growing radii, and each structure alone
ROI_REALISATION = {"Microstructure/Region of interest/Realisation half "
                   "width": "30"}
ROI_RADII = [5, 10, 15, 20, 30]
ROI_STRUCTURES = [
    ("layers only", {"Microstructure/Lobules": "false",
                     "Microstructure/Ligaments/Enabled": "false"}),
    ("septa only", {"Microstructure/Ligaments/Enabled": "false"}),
    ("ligaments only", {"Microstructure/Lobules": "false"})]


def roi():
    """The region of interest's radius and structures at the scene's
    discretisation (seed 1): depth and stiffness against the largest
    region, and the cost."""
    forces = scene_forces()
    rows = []
    cases = [(f"radius {r}", f"roi_r{r}",
              {**ROI_REALISATION,
               "Microstructure/Region of interest/Radius": str(r)})
             for r in ROI_RADII]
    cases += [(label, "roi_" + label.replace(" ", "_"),
               {**ROI_REALISATION, **overrides})
              for label, overrides in ROI_STRUCTURES]
    for label, name, overrides in cases:
        s = run(SCENE, name, overrides)
        rows.append({"case": label,
                     "stiffness_N_per_mm": s["stiffness_N_per_mm"] if s
                     else "", **result_columns(s, forces)})
    reference = rows[len(ROI_RADII) - 1]  # the largest region
    for r in rows:
        r["stiffness_change"] = (
            r["stiffness_N_per_mm"] / reference["stiffness_N_per_mm"] - 1
            if r["stiffness_N_per_mm"] != "" else "")
    fields = ["case", "stiffness_N_per_mm", "stiffness_change",
              "wall_time_s"] + [f"depth_mm_at_{f}N" for f in forces]
    write_csv(os.path.join(OUT, "forearm_roi.csv"), fields, rows)
    for r in rows:
        print(f"{r['case']:16s} " + ", ".join(
            f"{k}: {v:.4g}" for k, v in r.items()
            if k != "case" and v != ""))


# nu = 0.4999 in the fat; the Q2-P1 pair only to 1.0 N (its crawl beyond
# 1.5 N is not what this compares)
FAT_NU = {f"Layer stack/{layer}/Poisson's ratio": "0.4999"
          for layer in ["SAT", "DAT"]}
EVERY_LAYER_NU = {f"Layer stack/{layer}/Poisson's ratio": "0.4999"
                  for layer in ["skin", "SAT", "SM", "DAT", "deep"]}
Q2P1_TO_1N = {**Q2P1, **ogrid(8, 0.3, 1.6),
              "Punch/Forces": "0.35, 0.5, 0.75, 1.0"}


def poisson():
    """The fat's Poisson ratio 0.4999 beside 0.49, on the scene's
    discretisation and on Q2-P1: depth, stiffness and Newton iterations."""
    forces = scene_forces()
    rows = []
    for label, name, overrides in [
            ("Q1-P0 scene, nu 0.49", "bonded_Q1-P0_n12_h0.2", {}),
            ("Q1-P0 scene, fat nu 0.4999", "nu4999_Q1-P0_n12_h0.2", FAT_NU),
            ("Q1-P0 scene, every layer nu 0.4999",
             "nu4999_every_layer_Q1-P0_n12_h0.2", EVERY_LAYER_NU),
            # the convergence study's run (stopped near 1.7 N)
            ("Q2-P1 n8, nu 0.49", "bonded_Q2-P1_n8_h0.3",
             {**Q2P1, **ogrid(8, 0.3, 1.6)}),
            ("Q2-P1 n8, fat nu 0.4999", "nu4999_Q2-P1_n8_to_1N",
             {**Q2P1_TO_1N, **FAT_NU})]:
        s = run(SCENE, name, overrides)
        rows.append({"case": label, "dofs": s["dofs"] if s else "",
                     **solver_columns(s), **result_columns(s, forces)})
    fields = ["case", "dofs", "stiffness_N_per_mm", "newton_iterations",
              "wall_time_s"] + [f"depth_mm_at_{f}N" for f in forces]
    write_csv(os.path.join(OUT, "forearm_poisson.csv"), fields, rows)
    for base, incompressible in [(rows[0], rows[1]), (rows[0], rows[2]),
                                 (rows[3], rows[4])]:
        change = [f"{f} N {d / b - 1:+.2%}" for f in forces
                  for b, d in [(base[f"depth_mm_at_{f}N"],
                                incompressible[f"depth_mm_at_{f}N"])]
                  if b != "" and d != ""]
        print(f"{incompressible['case']}: depth " + ", ".join(change))


FRICTION_COEFFICIENTS = [0.2, 0.5, 0.8]


def friction():
    """Coulomb friction on the flat face between the bonded and the
    frictionless face: depth, stiffness, Newton iterations."""
    forces = scene_forces()
    cases = [("bonded (scene)", "bonded_Q1-P0_n12_h0.2", {})]
    cases += [(f"friction mu {mu}", f"friction_mu{mu}_Q1-P0_n12_h0.2",
               {"Punch/Contact": "friction",
                "Punch/Friction coefficient": str(mu)})
              for mu in FRICTION_COEFFICIENTS]
    cases += [("frictionless", "frictionless_Q1-P0_n12_h0.2",
               {"Punch/Contact": "frictionless"})]
    rows = []
    for label, name, overrides in cases:
        s = run(SCENE, name, overrides)
        rows.append({"case": label, **solver_columns(s),
                     **result_columns(s, forces)})
    fields = ["case", "stiffness_N_per_mm", "newton_iterations",
              "wall_time_s"] + [f"depth_mm_at_{f}N" for f in forces]
    write_csv(os.path.join(OUT, "forearm_friction.csv"), fields, rows)
    for r in rows:
        print(f"{r['case']:16s} " + ", ".join(
            f"{v:.3f}" if isinstance(v, float) else str(v)
            for k, v in r.items() if k.startswith("depth") and v != ""))


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(os.path.join(OUT, "forearm_convergence.csv")) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in r:
            if key == "dofs" or key.startswith("depth_mm"):
                r[key] = float(r[key]) if r[key] != "" else ""
    forces = scene_forces()
    bars = uncertainty("bonded", forces,
                       [r for r in rows if r["contact"] == "bonded"])
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    for ax, contact in zip(axes, ["bonded", "frictionless"]):
        for f, colour in [(0.35, "tab:blue"), (1.0, "tab:orange"),
                          (1.5, "tab:green"), (1.8, "tab:red")]:
            key = f"depth_mm_at_{f}N"
            for label, marker in [("Q1-P0", "o-"), ("Q2-P1", "D")]:
                pts = [(float(r["dofs"]), float(r[key])) for r in rows
                       if r["contact"] == contact and r[key] and
                       r["discretisation"] == label]
                if pts:
                    ax.semilogx(*zip(*sorted(pts)), marker, color=colour,
                                label=f"{label}, {f} N")
            scene = [r for r in rows if r["contact"] == contact and
                     (r["discretisation"], r["mesh"]) == SCENE_CASE]
            if contact == "bonded" and scene and scene[0][key] != "" and \
                    bars[forces.index(f)] is not None:
                ax.errorbar(scene[0]["dofs"], scene[0][key],
                            yerr=bars[forces.index(f)], color=colour,
                            capsize=4, lw=1)
        ax.set_xlabel("DoFs")
        ax.set_title(f"the real indenter, {contact} flat face (scene: Q1-P0 "
                     f"{SCENE_CASE[1]}, with its error bar)", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
    axes[0].set_ylabel("depth [mm]")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "forearm_convergence.png"), dpi=110)
    print("wrote benchmarks/forearm/results/forearm_convergence.png")


if __name__ == "__main__":
    command = sys.argv[1] if len(sys.argv) > 1 else ""
    if command == "convergence":
        convergence()
    elif command == "seeds":
        seeds(int(sys.argv[2]) if len(sys.argv) > 2 else 10)
    elif command == "herlin":
        herlin()
    elif command == "roi":
        roi()
    elif command == "poisson":
        poisson()
    elif command == "friction":
        friction()
    elif command == "plot":
        plot()
    else:
        sys.exit(__doc__)
