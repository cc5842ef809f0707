#!/usr/bin/python3
"""ssc's visco-elastic layers against an independent code: the force
relaxation of the layered, bonded punch whose fat layers (SAT, DAT) carry
one deviatoric Prony term (g = 0.39, tau = 20 s), the other layers
elastic, pressed over 0.1 s and held to 80 s.

The reference is CalculiX's (visco_relaxation_calculix.py: the standard
linear solid built from an elastic and a Maxwell element set on the same
nodes, converged in mesh and time, results/visco_relaxation_calculix.csv).
ssc runs visco_relaxation_punch.prm: prm/punch.prm's layers and punch
(Q2-P1, 60 mm square patch with its sides fixed, against CalculiX's
cylinder of radius 30 mm with a fixed wall), every layer neo-Hookean at
0.005 mm (linear to about 1e-3), ssc's own Prony law and time steps (2
over the ramp, 40 over the hold growing by 1.08). Compared: the force
relaxation F(t) / F(0.1 s), which the mesh and the patch's shape hardly
touch, and the force itself (scaled to CalculiX's 0.5 mm), which carries
ssc's discretisation error and the square-versus-cylinder difference.
ssc's force at CalculiX's times is interpolated in log t between its step
ends (steps at most 8 % apart in time on a smooth exponential: the
interpolation's error is below 1e-4 of F).

The relaxation ratio's difference is ssc's spatial discretisation (the
time steps are good to 1e-5, benchmarks/forearm/visco_correspondence.py):
the fully relaxed limit, F(long-term) / F(instantaneous), of elastic runs
with the fat at its instantaneous and at its long-term moduli, on the
shipped mesh and one refinement (Q2-P1, 26k and 201k DoFs), against
CalculiX's static runs of the same two elastic problems.

Writes results/visco_relaxation_check.csv (the times, then the limit
rows) and .png.

    /usr/bin/python3 benchmarks/finite_strain_vs_calculix/visco_relaxation_check.py [--plot-only]
"""
import csv, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

PRM = os.path.join(HERE, "visco_relaxation_punch.prm")
REFERENCE = os.path.join(HERE, "results", "visco_relaxation_calculix.csv")
CHECKS = os.path.join(HERE, "results", "visco_relaxation_calculix_checks.csv")
RESULTS = os.path.join(HERE, "results", "visco_relaxation_check.csv")
FOLDER = os.path.join(ROOT, "output", "benchmarks", "visco_relaxation_check")
SSC_DEPTH, CCX_DEPTH = 0.005, 0.5
G = 0.39  # the fat's relative modulus in visco_relaxation_punch.prm


def interpolate(times, values, t):
    """values at t, linear in log t between the two step ends around it."""
    for (t0, v0), (t1, v1) in zip(zip(times, values),
                                  zip(times[1:], values[1:])):
        if t0 <= t <= t1:
            w = math.log(t / t0) / math.log(t1 / t0)
            return (1 - w) * v0 + w * v1
    raise ValueError(f"t = {t} outside the run's steps")


def measure():
    run = ssc_runner.run(PRM, {}, output_dir=FOLDER, name="ssc",
                         timeout=3600, check=True)
    s = run.summary()
    times, forces = s["time_s"], s["force_N"]
    print(f"ssc: {run.wall_s:.1f} s, {s['dofs']} DoFs, {len(times)} steps, "
          f"{s['solver']['newton_iterations']} Newton iterations", flush=True)
    reference = list(csv.DictReader(open(REFERENCE)))
    scale = CCX_DEPTH / SSC_DEPTH
    f_ramp = interpolate(times, forces, 0.1)
    rows = []
    for r in reference:
        t = float(r["time_s"])
        force = scale * interpolate(times, forces, t)
        ratio = force / (scale * f_ramp)
        rows.append({
            "time_s": t, "ssc_force_N": force,
            "calculix_force_N": float(r["force_N"]),
            "force_difference": force / float(r["force_N"]) - 1,
            "ssc_ratio": ratio, "calculix_ratio": float(r["force_ratio"]),
            "ratio_difference": ratio / float(r["force_ratio"]) - 1,
            "calculix_ratio_uncertainty": float(r["uncertainty_ratio"]),
            "ssc_wall_s": round(run.wall_s, 1), "ssc_dofs": s["dofs"]})
        print(f"t = {t:5.1f} s: F/F(0.1) ssc {ratio:.6f}, CalculiX "
              f"{float(r['force_ratio']):.6f} "
              f"({rows[-1]['ratio_difference']:+.1e}); F "
              f"{rows[-1]['force_difference']:+.2e}", flush=True)
    rows += elastic_limits()
    ssc_runner.write_rows(RESULTS, rows)


def elastic_limits():
    """F(long-term) / F(instantaneous) of ssc's elastic runs on two meshes,
    against CalculiX's finest static pair."""
    checks = [r for r in csv.DictReader(open(CHECKS))
              if r["check"] == "punch static" and r["case"] == "long_term"]
    finest = max(checks, key=lambda r: int(r["level"]))
    reference = 1 + float(finest["relative_error"])
    E, nu = ssc_runner.layer_moduli(os.path.join(FOLDER, "ssc"))
    rows = []
    for level in (0, 1):
        forces = []
        for fraction in (1.0, 1 - G):
            overrides = dict(ssc_runner.relaxed_layer_overrides(E, nu,
                                                                fraction),
                             **{"Mesh/Global refinements": level})
            run = ssc_runner.run(PRM, overrides, output_dir=FOLDER,
                                 name=f"elastic{level}_{fraction}",
                                 timeout=3600, check=True)
            forces.append(run.summary()["force_N"][-1])
            dofs = run.summary()["dofs"]
        ratio = forces[1] / forces[0]
        rows.append({"time_s": "long-term limit", "ssc_ratio": ratio,
                     "calculix_ratio": reference,
                     "ratio_difference": ratio / reference - 1,
                     "ssc_dofs": dofs})
        print(f"fully relaxed F / instantaneous F, {dofs} DoFs: ssc "
              f"{ratio:.6f}, CalculiX {reference:.6f} "
              f"({ratio / reference - 1:+.1e})", flush=True)
    return rows


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in csv.DictReader(open(RESULTS))
            if r["time_s"] != "long-term limit"]
    t = [float(r["time_s"]) for r in rows]
    fig, (ax, err) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax.plot(t, [float(r["calculix_ratio"]) for r in rows], "o-",
            label="CalculiX (elastic + Maxwell element sets, converged)")
    ax.plot(t, [float(r["ssc_ratio"]) for r in rows], "x", ms=9,
            label="ssc (Prony law, time steps)")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("punch force / force at the end of the ramp")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    err.semilogy(t[1:], [abs(float(r["ratio_difference"])) for r in rows[1:]],
                 "o-", label="relaxation F(t)/F(0.1): ssc vs CalculiX")
    err.semilogy(t, [abs(float(r["force_difference"])) for r in rows], "s-",
                 label="force itself (mesh, square vs cylinder)")
    err.axhline(0.01, color="0.5", ls=":", lw=1, label="1 %")
    err.set_xlabel("time (s)")
    err.set_ylabel("relative difference")
    err.legend(fontsize=8)
    err.grid(alpha=0.3)
    fig.suptitle("Layered punch held at its depth, fat one Prony term "
                 "(0.39, 20 s): ssc against CalculiX", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.splitext(RESULTS)[0] + ".png", dpi=120)


if __name__ == "__main__":
    if "--plot-only" not in sys.argv:
        measure()
    plot()
