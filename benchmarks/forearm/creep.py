#!/usr/bin/python3
"""Creep and relaxation of the forearm under the main scene's indenter
(prm/forearm_creep.prm, prm/forearm_relaxation.prm: the fat layers
visco-elastic with Sims et al. 2010's Prony term, relative modulus 0.39,
relaxation time 700 s): the curves, the error of their fixed time steps,
and the two elastic limits of the law on the whole scene.

Runs (two MPI ranks, V-cycle, no fields), one after the other:

- creep and relaxation as shipped (4 ramp steps, 12 hold steps growing by
  1.3) and with every step halved (8 ramp steps, 24 hold steps growing by
  sqrt(1.3): every other end time is a shipped one): the difference at the
  shared times measures the time-step error of the shipped steps (the
  integration is second order, so the halved run's own error is about a
  quarter of that);
- the elastic limits: creep with the relaxation time 1e-6 s (relaxed at
  once) against the elastic scene with the fat's long-term moduli (shear
  modulus g_inf mu, bulk modulus unchanged), and with 1e12 s (never
  relaxes) against the elastic scene with the instantaneous moduli, both
  elastic runs straight to 1 N.

Writes benchmarks/forearm/results/creep.csv (one row per run and time),
creep_runs.csv (one row per run) and creep.png.

    /usr/bin/python3 benchmarks/forearm/creep.py [--plot-only]
"""
import csv, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

CREEP = os.path.join(ROOT, "prm", "forearm_creep.prm")
RELAXATION = os.path.join(ROOT, "prm", "forearm_relaxation.prm")
CURVES = os.path.join(HERE, "results", "creep.csv")
RUNS = os.path.join(HERE, "results", "creep_runs.csv")
FAT = ("SAT", "DAT")
G = 0.39  # the shipped relative modulus

HALVED = {"Time/Ramp steps": 8, "Time/Hold steps": 24,
          "Time/Hold step growth": math.sqrt(1.3)}


def relaxation_time(tau):
    return {f"Layer stack/{layer}/Viscoelasticity/Relaxation times": tau
            for layer in FAT}


def elastic(moduli=None):
    """The elastic scene straight to 1 N (no time, no Prony terms), the
    fat at moduli (E, nu) if given."""
    overrides = {"Time/Loading history": "none", "Punch/Forces": 1.0}
    for layer in FAT:
        overrides[f"Layer stack/{layer}/Viscoelasticity/Relative moduli"] = ""
        overrides[f"Layer stack/{layer}/Viscoelasticity/Relaxation times"] = ""
        if moduli:
            overrides[f"Layer stack/{layer}/Young's modulus"] = moduli[0]
            overrides[f"Layer stack/{layer}/Poisson's ratio"] = moduli[1]
    return overrides


def long_term_moduli(E, nu, g):
    """(E, nu) of the shear modulus (1 - g) mu and the same bulk modulus."""
    mu, kappa = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
    mu_long = (1 - g) * mu
    return (9 * kappa * mu_long / (3 * kappa + mu_long),
            (3 * kappa - 2 * mu_long) / (2 * (3 * kappa + mu_long)))


def variants(fat):
    E_long, nu_long = long_term_moduli(*fat, G)
    return [
        ("creep", CREEP, {}),
        ("creep, steps halved", CREEP, HALVED),
        ("relaxation", RELAXATION, {}),
        ("relaxation, steps halved", RELAXATION, HALVED),
        ("creep, tau 1e-6 s", CREEP, relaxation_time(1e-6)),
        ("elastic, long-term fat moduli", CREEP,
         elastic((E_long, nu_long))),
        ("creep, tau 1e12 s", CREEP, relaxation_time(1e12)),
        ("elastic, instantaneous moduli", CREEP, elastic()),
    ]


def measure():
    folder = os.path.join(ROOT, "output", "benchmarks", "creep")
    curves, runs = [], []
    # the fat's moduli from a check of the shipped parameters
    probe = ssc_runner.run(CREEP, {"Time/Hold steps": 1,
                                   "Time/Hold time": 1e-3,
                                   "Time/Ramp steps": 1, "Punch/Forces": 0.01,
                                   "Run/Write fields": "false"},
                           output_dir=folder, name="probe", ranks=2,
                           timeout=900, check=True)
    fat = ssc_runner.layer_moduli(probe.folder)
    for k, (label, prm, overrides) in enumerate(variants(fat)):
        overrides = dict(overrides, **{"Run/Write fields": "false"})
        run = ssc_runner.run(prm, overrides, output_dir=folder,
                             name=f"run{k}", ranks=2, timeout=1800)
        print(f"{label}: exit {run.returncode}, {run.wall_s:.1f} s",
              flush=True)
        if not run.ok:
            print(run.stdout[-2000:], run.stderr[-2000:])
            continue
        s = run.summary()
        times = s.get("time_s", [None])
        forces, depths = s["force_N"], s["depth_mm"]
        for t, f, d in zip(times, forces, depths):
            curves.append({"run": label, "time_s": t, "force_N": f,
                           "depth_mm": d})
        runs.append({"run": label, "wall_s": round(run.wall_s, 1),
                     "newton_iterations": s["solver"]["newton_iterations"],
                     "final_force_N": forces[-1], "final_depth_mm": depths[-1],
                     "depth_at_1s_mm": depths[3] if len(depths) > 3 and
                     times[3] == 1 else "",
                     "relaxed_fraction": s.get("relaxed_fraction", ""),
                     "dofs": s["dofs"]})
    os.makedirs(os.path.dirname(CURVES), exist_ok=True)
    for name, rows in ((CURVES, curves), (RUNS, runs)):
        with open(name, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)


def read(name):
    with open(name) as f:
        return list(csv.DictReader(f))


def curve(rows, label):
    return [(float(r["time_s"]), float(r["force_N"]), float(r["depth_mm"]))
            for r in rows if r["run"] == label and r["time_s"]]


def step_error(rows, label, column):
    """Largest relative difference between a run and its halved-step run at
    the shipped run's times."""
    shipped = {round(t, 6): (f, d) for t, f, d in curve(rows, label)}
    worst = 0.0
    for t, f, d in curve(rows, label + ", steps halved"):
        if round(t, 6) in shipped:
            a = shipped[round(t, 6)][column]
            worst = max(worst, abs(a - (f, d)[column]) / abs((f, d)[column]))
    return worst


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read(CURVES)
    limits = {r["run"]: float(r["final_depth_mm"]) for r in read(RUNS)}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, kind, column, unit in ((axes[0], "creep", 2, "depth (mm)"),
                                   (axes[1], "relaxation", 1, "force (N)")):
        for label, style in ((kind, "o-"), (kind + ", steps halved", "x--")):
            points = curve(rows, label)
            if not points:
                continue
            ax.plot([0] + [p[0] for p in points],
                    [0] + [p[column] for p in points], style, ms=4,
                    label=label)
        if kind == "creep":
            for label, text in (("creep, tau 1e-6 s", "long-term (tau -> 0)"),
                                ("creep, tau 1e12 s",
                                 "instantaneous (tau -> infinity)")):
                if label in limits:
                    ax.axhline(limits[label], color="0.5", ls=":", lw=1)
                    ax.text(600, limits[label], text, fontsize=7,
                            ha="right", va="bottom", color="0.3")
        error = step_error(rows, kind, column - 1)
        ax.set_title(f"{kind}: fat Prony term 0.39, 700 s (Sims 2010)\n"
                     f"shipped steps vs halved: {100 * error:.3f} % at most",
                     fontsize=9)
        ax.set_xlabel("time (s)")
        ax.set_ylabel("punch " + unit)
        ax.set_xlim(left=0)
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="lower right")
    fig.suptitle("Forearm under the 5 mm punch: 1 N held 10 min (creep), "
                 "6.7 mm held 10 min (relaxation)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "results", "creep.png"), dpi=120)


if __name__ == "__main__":
    if "--plot-only" not in sys.argv:
        measure()
    plot()
