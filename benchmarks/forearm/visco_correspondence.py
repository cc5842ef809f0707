#!/usr/bin/python3
"""An independent check of the visco-elastic time integration on a whole,
inhomogeneous scene: the elastic-viscoelastic correspondence principle.

The layered punch of visco_layered_punch.prm is linear (tiny force, no
septa, ligaments or contact), its fat layers visco-elastic with one
deviatoric Prony term (g = 0.39, tau = 20 s), the other layers elastic.
For a linear visco-elastic body the Laplace transform of the depth under
the force history f(t) is

    d^(s) = C(mu~(s)) f^(s),   mu~(s) = mu (g_inf + g s tau / (1 + s tau)),

where C(mu') is the compliance (depth per force) of the *elastic* body
whose fat has shear modulus mu' and the unchanged bulk modulus, and f^(s)
= F (1 - e^{-s t_r}) / (t_r s^2) for a force ramped over t_r and held.
The depth is recovered by the Gaver-Stehfest inversion (N = 12, and N = 10
for its own uncertainty), every C from an elastic ssc run (no time, the
fat's E and nu set from mu~(s)). That is a different method (elastic
solves and an inverse transform instead of time steps with internal
variables) for the same model; the visco-elastic run with the shipped
steps and with halved steps is compared with it at six times of the hold.
The inversion itself is checked on the closed form of a standard linear
solid under the same ramp.

Writes benchmarks/forearm/results/visco_correspondence.csv and .png.

    /usr/bin/python3 benchmarks/forearm/visco_correspondence.py [--plot-only]
"""
import csv, math, os, sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

PRM = os.path.join(HERE, "visco_layered_punch.prm")
RESULTS = os.path.join(HERE, "results", "visco_correspondence.csv")
FOLDER = os.path.join(ROOT, "output", "benchmarks", "visco_correspondence")
FAT = ("SAT", "DAT")
G, TAU, T_RAMP, FORCE = 0.39, 20.0, 0.1, 1e-5
N_NODES, DEGREE = 24, 8
HALVED = {"Time/Ramp steps": 4, "Time/Hold steps": 80,
          "Time/Hold step growth": math.sqrt(1.08)}


def stehfest_weights(n):
    half = n // 2
    weights = []
    for k in range(1, n + 1):
        total = 0.0
        for j in range((k + 1) // 2, min(k, half) + 1):
            total += (j ** half * math.factorial(2 * j) /
                      (math.factorial(half - j) * math.factorial(j) *
                       math.factorial(j - 1) * math.factorial(k - j) *
                       math.factorial(2 * j - k)))
        weights.append((-1) ** (k + half) * total)
    return weights


def invert(transform, t, n):
    """Gaver-Stehfest: f(t) from its Laplace transform."""
    a = math.log(2.0) / t
    return a * sum(w * transform((k + 1) * a)
                   for k, w in enumerate(stehfest_weights(n)))


def ramp_transform(s):
    """Laplace transform of a unit force ramped over T_RAMP and held."""
    return -math.expm1(-s * T_RAMP) / (T_RAMP * s * s)


def relative_shear(s):
    """mu~(s) / mu: the s-multiplied transform of the relaxation function."""
    return (1 - G) + G * s * TAU / (1 + s * TAU)


def sls_ramp_creep(t):
    """Closed form: shear strain of a standard linear solid (mu = 1, the
    series above) under a unit shear stress ramped over T_RAMP: the
    creep compliance J(t) = 1/g_inf - (1/g_inf - 1) e^{-t/tau_c}, tau_c =
    tau / g_inf, convolved with the ramp."""
    g_inf, tau_c = 1 - G, TAU / (1 - G)
    a = 1 / g_inf - 1

    def integral(x):  # int_0^x J(u) du
        return x / g_inf - a * tau_c * (1 - math.exp(-x / tau_c))
    return (integral(t) - (integral(t - T_RAMP) if t > T_RAMP else 0)) / T_RAMP


def measure():
    rows = []
    visco = {}
    for label, overrides in (("time steps", {}),
                             ("time steps halved", HALVED)):
        run = ssc_runner.run(PRM, overrides, output_dir=FOLDER,
                             name=label.replace(" ", "_"), timeout=1800,
                             check=True)
        s = run.summary()
        visco[label] = dict(zip((round(t, 9) for t in s["time_s"]),
                                s["depth_mm"]))
        print(f"{label}: {run.wall_s:.1f} s, {s['dofs']} DoFs, "
              f"{len(s['time_s'])} steps", flush=True)
        rows.append({"what": label, "wall_s": round(run.wall_s, 1),
                     "dofs": s["dofs"]})
    E, nu = ssc_runner.layer_moduli(os.path.join(FOLDER, "time_steps"))

    # the compliance C(phi) of the elastic body whose fat has the shear
    # modulus phi mu, phi = mu~(s) / mu in (g_inf, 1], at Chebyshev points,
    # one run at a time (about a second each). Stehfest's weights sum to
    # about 3e7 in magnitude (N = 12), so the solves' round-off (about 1e-8
    # of C) must not reach it: C is smooth in phi, and a least-squares
    # polynomial through the points removes the noise (its residual is
    # printed: it is the solves' noise).
    g_inf = 1 - G
    nodes = [g_inf + (1 - g_inf) * 0.5 * (1 - math.cos(math.pi * (i + 0.5) /
                                                       N_NODES))
             for i in range(N_NODES)]
    compliances, elastic_wall = [], 0.0
    for i, phi in enumerate(nodes):
        run = ssc_runner.run(PRM, dict(ssc_runner.relaxed_layer_overrides(
                                 E, nu, phi), **{"Run/Test mode": "true"}),
                             output_dir=FOLDER, name=f"elastic{i}",
                             timeout=900, check=True)
        compliances.append(run.summary()["depth_mm"][-1] / FORCE)
        elastic_wall += run.wall_s
    fit = numpy.polynomial.Chebyshev.fit(nodes, compliances, DEGREE)
    noise = max(abs(fit(x) / c - 1) for x, c in zip(nodes, compliances))
    print(f"{N_NODES} elastic runs, {elastic_wall:.0f} s in all; degree "
          f"{DEGREE} fit, largest residual {noise:.1e} of C", flush=True)
    rows.append({"what": "compliance fit", "fit_residual": noise,
                 "elastic_runs": N_NODES, "wall_s": round(elastic_wall, 1)})

    def transform(s):
        return fit(relative_shear(s)) * FORCE * ramp_transform(s)

    # every step end of the shipped run after the ramp's kink; the halved
    # run has every one of them among its own
    for t in sorted(visco["time steps"]):
        if t < 1.5:
            continue
        reference = invert(transform, t, 12)
        row = {"what": "depth", "time_s": t, "correspondence_mm": reference,
               "inversion_uncertainty": abs(invert(transform, t, 14) /
                                            reference - 1),
               "sls_inversion_error": abs(
                   invert(lambda s: ramp_transform(s) / relative_shear(s),
                          t, 12) / sls_ramp_creep(t) - 1)}
        for label in visco:
            depth = visco[label][t]
            row[f"{label} mm"] = depth
            row[f"{label} error"] = abs(depth / reference - 1)
        rows.append(row)
        print(f"t = {t:6.2f} s: correspondence {reference:.6e} mm, "
              f"time steps error {row['time steps error']:.1e}, halved "
              f"{row['time steps halved error']:.1e}, inversion N12-N14 "
              f"{row['inversion_uncertainty']:.1e}, SLS inversion "
              f"{row['sls_inversion_error']:.1e}", flush=True)
    fields = []
    for row in rows:
        fields += [k for k in row if k not in fields]
    os.makedirs(os.path.dirname(RESULTS), exist_ok=True)
    with open(RESULTS, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in csv.DictReader(open(RESULTS)) if r["what"] == "depth"]
    t = [float(r["time_s"]) for r in rows]
    fig, (ax, err) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax.plot(t, [1e3 * float(r["correspondence_mm"]) for r in rows], "o-",
            label="correspondence + Stehfest (elastic runs)")
    ax.plot(t, [1e3 * float(r["time steps mm"]) for r in rows], "x",
            ms=7, label="visco-elastic run, time steps")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("punch depth (um) under 1e-5 N")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    for key, label in (("time steps error", "time steps"),
                       ("time steps halved error", "steps halved"),
                       ("inversion_uncertainty", "inversion N=12 vs 14"),
                       ("sls_inversion_error", "inversion on the SLS")):
        err.semilogy(t, [max(float(r[key]), 1e-12) for r in rows], "o-",
                     label=label)
    err.axhline(0.01, color="0.5", ls=":", lw=1, label="1 %")
    err.set_xlabel("time (s)")
    err.set_ylabel("relative difference")
    err.legend(fontsize=8)
    err.grid(alpha=0.3)
    fig.suptitle("Layered punch, fat one Prony term (0.39, 20 s): time "
                 "integration against the correspondence principle",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.splitext(RESULTS)[0] + ".png", dpi=120)


if __name__ == "__main__":
    if "--plot-only" not in sys.argv:
        measure()
    plot()
