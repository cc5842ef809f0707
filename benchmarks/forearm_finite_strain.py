#!/usr/bin/python3
"""The finite-strain forearm indentation (prm/forearm_indentation.prm, the
main scene): how far its depths are mesh-converged, how much the lobule
realisation moves them, and the reference model's set-up reproduced.

    /usr/bin/python3 benchmarks/forearm_finite_strain.py convergence
    /usr/bin/python3 benchmarks/forearm_finite_strain.py seeds [N]
    /usr/bin/python3 benchmarks/forearm_finite_strain.py herlin
    /usr/bin/python3 benchmarks/forearm_finite_strain.py roi
    /usr/bin/python3 benchmarks/forearm_finite_strain.py plot

convergence: the scene at every force with a bonded and a frictionless
punch face (the rounded edge in frictionless contact in both), Q1 with the
cell's mean dilatation (Q1-P0) on the scene's mesh and refined once and
twice towards the punch edge, Q2-P0 and Q2 u-p (Q2-P1, Formulation =
mixed) on the scene's mesh; lobule seed 1 throughout. The depth
uncertainty of the scene's discretisation at each force is its distance
from the finest run that reached that force plus that run's distance from
the next finest (the reference's own error, bounded by how much the two
finest discretisations disagree); it is what Punch/Depth uncertainty in
the scene's prm holds (the script says whether the two agree).

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

Each run is kept in benchmarks/results/forearm_runs/<case>/ (summary and
force-displacement table only) and not repeated; delete a folder to rerun.
Writes benchmarks/results/forearm_convergence.csv, forearm_seeds.csv,
forearm_herlin.csv, forearm_roi.csv and forearm_convergence.png. 2 MPI ranks.
"""
import csv, json, os, shutil, statistics, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SSC = os.path.join(ROOT, "build", "bin", "ssc")
SCENE = os.path.join(ROOT, "prm", "forearm_indentation.prm")
HERLIN = os.path.join(ROOT, "prm", "forearm_indentation_herlin2014.prm")
OUT = os.path.join(ROOT, "benchmarks", "results")
RUNS = os.path.join(OUT, "forearm_runs")
RANKS = 2
BASE = {"Run/Write fields": "false", "Punch/Section": "false",
        "Punch/Profile length": "0"}
LR = "Mesh/Region of interest/Local refinements"
Q1 = {"Elasticity/Degree": "1", "Elasticity/Formulation": "mean dilatation"}
Q2P0 = {"Elasticity/Degree": "2",
        "Elasticity/Formulation": "mean dilatation"}
Q2P1 = {"Elasticity/Degree": "2", "Elasticity/Formulation": "mixed"}
# (contact, discretisation, overrides, levels), coarse to fine; the last
# entries of each contact are the finest
CONVERGENCE = [
    ("bonded", "Q1-P0", Q1, [0, 1, 2]),
    ("bonded", "Q2-P0", Q2P0, [0]),
    ("bonded", "Q2-P1", Q2P1, [0]),
    # frictionless: Q1-P0 only so far (Q2 with a frictionless face crawled
    # in the hard cases, benchmarks/README.md)
    ("frictionless", "Q1-P0", Q1, [0, 1]),
]
# the scene's discretisation
SCENE_CASE = ("Q1-P0", 0)
# the reference model's set-up (Herlin et al. 2014): a regular 2 mm grid of
# hexahedra (no mesh line on the punch's circle), Q1 displacement,
# corotational, nu 0.49, its moduli; the rounded punch edge in contact as
# in the scene
HERLIN_SETUP = {"Elasticity/Degree": "1",
                "Elasticity/Formulation": "displacement",
                "Mesh/Cell size": "2", "Mesh/Core half width": "30",
                "Mesh/Fitted circle radius": "0", LR: "0"}
for layer in ["skin", "SAT", "SM", "DAT", "deep"]:
    HERLIN_SETUP[f"Layer stack/{layer}/Material model"] = "corotational"


def run(prm, name, overrides):
    """Runs ssc once (or reads the kept result): summary and steps."""
    folder = os.path.join(RUNS, name)
    summary_file = os.path.join(folder, "summary.json")
    if not os.path.exists(summary_file):
        with tempfile.TemporaryDirectory() as tmp:
            args = ["mpirun", "-np", str(RANKS), SSC, prm,
                    "-s", f"Run/Output directory={tmp}",
                    "-s", "Run/Name=run"]
            for key, value in {**BASE, **overrides}.items():
                args += ["-s", f"{key}={value}"]
            env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                       OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
            print("running", name, flush=True)
            result = subprocess.run(args, env=env, capture_output=True,
                                    text=True)
            os.makedirs(folder, exist_ok=True)
            with open(os.path.join(folder, "log.txt"), "w") as f:
                f.write(result.stdout + result.stderr)
            if result.returncode != 0:
                print(f"  {name} failed (exit {result.returncode}); "
                      f"log in {folder}", flush=True)
                return None
            for f in ["summary.json", "force_displacement.csv"]:
                shutil.copy(os.path.join(tmp, "run", f), folder)
    if not os.path.exists(summary_file):
        return None
    with open(summary_file) as f:
        return json.load(f)


def depths_at(summary, forces):
    """The run's depth at each scene force (None where it did not get)."""
    if summary is None:
        return [None] * len(forces)
    reached = dict(zip([round(f, 6) for f in summary["force_N"]],
                       summary["depth_mm"]))
    return [reached.get(round(f, 6)) for f in forces]


def scene_forces():
    for line in open(SCENE):
        if line.strip().startswith("set Forces"):
            return [float(v) for v in line.split("=")[1].split(",")]
    raise RuntimeError("no Punch/Forces in " + SCENE)


def result_columns(summary, forces):
    """The columns every table shares: wall time and the depth per force
    (empty where the run failed or stopped short)."""
    columns = {"wall_time_s": round(summary["timings"]["total"], 1)
               if summary else ""}
    for f, d in zip(forces, depths_at(summary, forces)):
        columns[f"depth_mm_at_{f}N"] = "" if d is None else d
    return columns


def write_csv(path, fields, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    print("wrote", os.path.relpath(path, ROOT))


def convergence():
    forces = scene_forces()
    rows = []
    for contact, label, overrides, levels in CONVERGENCE:
        for level in levels:
            name = f"{contact}_{label}_lr{level}"
            s = run(SCENE, name, {**overrides, LR: str(level),
                                  "Punch/Contact": contact})
            row = {"contact": contact, "discretisation": label,
                   "level": level,
                   "dofs": s["dofs"] if s else "",
                   "wall_time_s": round(s["timings"]["total"], 1)
                   if s else "",
                   "newton_iterations": s["solver"]["newton_iterations"]
                   if s and "newton_iterations" in s["solver"] else ""}
            for f, d in zip(forces, depths_at(s, forces)):
                row[f"depth_mm_at_{f}N"] = "" if d is None else d
            rows.append(row)
    fields = ["contact", "discretisation", "level", "dofs", "wall_time_s",
              "newton_iterations"] + [f"depth_mm_at_{f}N" for f in forces]
    write_csv(os.path.join(OUT, "forearm_convergence.csv"), fields, rows)
    for contact in sorted({c[0] for c in CONVERGENCE}):
        uncertainty(contact, forces,
                    [r for r in rows if r["contact"] == contact])


def uncertainty(contact, forces, rows):
    """Prints the scene discretisation's depth uncertainty per force."""
    scene = [r for r in rows if (r["discretisation"], r["level"]) ==
             SCENE_CASE][0]
    # finest first: most DoFs
    ranked = sorted([r for r in rows if r["dofs"] != ""],
                    key=lambda r: -r["dofs"])
    values = []
    for f in forces:
        key = f"depth_mm_at_{f}N"
        reached = [r for r in ranked if r[key] != ""]
        if scene[key] == "" or len(reached) < 2 or reached[0] is scene:
            values.append(None)
            continue
        best, second = reached[0], reached[1]
        values.append(abs(scene[key] - best[key]) +
                      abs(best[key] - second[key]))
        print(f"{contact} {f} N: scene {scene[key]:.3f} mm, finest "
              f"{best['discretisation']} lr{best['level']} "
              f"{best[key]:.3f} mm, next {second['discretisation']} "
              f"lr{second['level']} {second[key]:.3f} mm -> "
              f"+-{values[-1]:.3f} mm")
    print(f"{contact}: Depth uncertainty = " +
          ", ".join("?" if v is None else f"{v:.2f}" for v in values))


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


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(os.path.join(OUT, "forearm_convergence.csv")) as f:
        rows = list(csv.DictReader(f))
    forces = [float(k[len("depth_mm_at_"):-1]) for k in rows[0]
              if k.startswith("depth_mm_at_")]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    for ax, contact in zip(axes, ["bonded", "frictionless"]):
        for label, marker in [("Q1-P0", "o-"), ("Q2-P0", "s"),
                              ("Q2-P1", "D")]:
            sel = [r for r in rows if r["contact"] == contact and
                   r["discretisation"] == label and r["dofs"]]
            for f in [0.35, 1.0, 1.8]:
                key = f"depth_mm_at_{f}N"
                pts = [(float(r["dofs"]), float(r[key])) for r in sel
                       if r[key]]
                if pts:
                    ax.semilogx(*zip(*pts), marker,
                                label=f"{label}, {f} N")
        ax.set_xlabel("DoFs")
        ax.set_title(f"{contact} punch face", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    axes[0].set_ylabel("depth [mm]")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "forearm_convergence.png"), dpi=110)
    print("wrote benchmarks/results/forearm_convergence.png")


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
    elif command == "plot":
        plot()
    else:
        sys.exit(__doc__)
