#!/usr/bin/python3
"""Does the in vivo stiffness of the MULTIS trials depend on how fast the
probe was pressed, and does ssc's visco-elastic fat predict that it
should?

Data: data/multis/indentation_trials.csv, one trial per subject and site
(752 with a rate, a force, a displacement and a stiffness). `Rate` is not
documented in the table or its source repository. Its values (median 6.4,
1-25) follow the trial's displacement (TotalStrain x Thickness; Spearman
0.84) and not its largest force (-0.04), so it is read here as a
displacement rate in mm/s, and T = displacement / Rate as the loading time
(median about 0.8 s). The stiffness is Total_Stiff (pressure over total
displacement, MPa/mm).

1. Per site: Spearman's rank correlation of stiffness with rate, with a
   bootstrap 95 % interval (2000 resamples of the trials).
2. Pooled, with each subject's and each site's own level removed (two-way
   additive fixed effects of log stiffness and log rate, by alternating
   means): the slope of log stiffness against log loading time (a
   visco-elastic tissue softens the slower it is loaded: a negative
   slope), with a bootstrap interval over subjects.
3. What the model predicts: a linear visco-elastic body with the Prony
   series g(t) loaded by a ramp of duration T has, at the ramp's end, the
   secant stiffness (1/T) int_0^T g(s) ds of its instantaneous one (exact
   for a homogeneous linear body; the forearm scene in time gives the same
   order, benchmarks/forearm/creep.py). Its slope in log T over the data's
   range of T, for the fat of prm/forearm_creep.prm (Sims et al. 2010,
   0.39 and 700 s) and for the ends of Zheng & Mak 1999's in vivo range
   (0.03-0.28, 0.05-8.9 s), and the fat's share of the compliance taken as
   1 (an upper bound: skin and muscle are elastic in the scene).

Writes benchmarks/identification/results/loading_rate.csv and
loading_rate.png.

    /usr/bin/python3 benchmarks/identification/loading_rate.py
"""
import csv, math, os

import numpy as np
from scipy import stats

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA = os.path.join(ROOT, "data", "multis", "indentation_trials.csv")
RESULTS = os.path.join(HERE, "results")
RNG = np.random.default_rng(7)
PRONY = {"fat of forearm_creep.prm (Sims 2010: 0.39, 700 s)": (0.39, 700.),
         "Zheng & Mak 1999, slow end (0.28, 8.9 s)": (0.28, 8.9),
         "Zheng & Mak 1999, fast end (0.03, 0.05 s)": (0.03, 0.05),
         "Zheng & Mak 1999, strongest (0.28, 1 s)": (0.28, 1.0)}


def trials():
    rows = []
    with open(DATA) as f:
        for r in csv.DictReader(f):
            try:
                rate, force = float(r["Rate"]), float(r["MaxForce"])
                stiffness = float(r["Total_Stiff"])
                displacement = float(r["TotalStrain"]) * float(r["Thickness"])
            except ValueError:
                continue
            if rate > 0 and force > 0 and stiffness > 0 and displacement > 0:
                rows.append((r["SubID"], r["Location"], rate, force,
                             stiffness, displacement))
    return rows


def remove_levels(values, subjects, sites, sweeps=50):
    """values less the additive subject and site levels (two-way fixed
    effects by alternating means)."""
    residual = values - values.mean()
    for _ in range(sweeps):
        for groups in (subjects, sites):
            for g in np.unique(groups):
                mask = groups == g
                residual[mask] -= residual[mask].mean()
    return residual


def within_slope(log_t, log_k, subjects, sites):
    x = remove_levels(log_t.copy(), subjects, sites)
    y = remove_levels(log_k.copy(), subjects, sites)
    return float(np.dot(x, y) / np.dot(x, x))


def model_slope(g, tau, t_low, t_high):
    """d log(secant stiffness) / d log T between t_low and t_high."""
    def secant(T):
        return 1 - g + g * tau / T * (1 - math.exp(-T / tau))
    return (math.log(secant(t_high)) - math.log(secant(t_low))) / \
        (math.log(t_high) - math.log(t_low))


def main():
    rows = trials()
    subjects = np.array([r[0] for r in rows])
    sites = np.array([r[1] for r in rows])
    rate = np.array([r[2] for r in rows])
    force = np.array([r[3] for r in rows])
    stiffness = np.array([r[4] for r in rows])
    displacement = np.array([r[5] for r in rows])
    loading_time = displacement / rate
    out = []
    for name, other in (("displacement", displacement), ("force", force)):
        out.append({"what": f"Spearman rho, rate vs {name} (what Rate is)",
                    "n": len(rows),
                    "value": round(stats.spearmanr(rate, other).correlation,
                                   3), "low_95": "", "high_95": ""})
    for site in sorted(set(sites)):
        m = sites == site
        rho = stats.spearmanr(rate[m], stiffness[m]).correlation
        idx = np.flatnonzero(m)
        boot = []
        for _ in range(2000):
            b = RNG.choice(idx, idx.size)
            boot.append(stats.spearmanr(rate[b], stiffness[b]).correlation)
        low, high = np.percentile(boot, [2.5, 97.5])
        out.append({"what": f"Spearman rho, stiffness vs rate, {site}",
                    "n": int(m.sum()), "value": round(rho, 3),
                    "low_95": round(low, 3), "high_95": round(high, 3)})
    log_t, log_k = np.log(loading_time), np.log(stiffness)
    slope = within_slope(log_t, log_k, subjects, sites)
    unique = np.unique(subjects)
    boot = []
    for _ in range(400):
        chosen = RNG.choice(unique, unique.size)
        idx = np.concatenate([np.flatnonzero(subjects == s) for s in chosen])
        # resampled subjects keep their own label per draw
        labels = np.concatenate([[f"{k}"] * int((subjects == s).sum())
                                 for k, s in enumerate(chosen)])
        boot.append(within_slope(log_t[idx], log_k[idx], labels, sites[idx]))
    low, high = np.percentile(boot, [2.5, 97.5])
    out.append({"what": "data: slope of log stiffness vs log loading time, "
                        "subject and site levels removed",
                "n": len(rows), "value": round(slope, 4),
                "low_95": round(low, 4), "high_95": round(high, 4)})
    t_low, t_high = np.percentile(loading_time, [10, 90])
    for name, (g, tau) in PRONY.items():
        out.append({"what": f"model: slope for {name}, T {t_low:.2f}-"
                            f"{t_high:.2f} s",
                    "n": "", "value": round(model_slope(g, tau, t_low,
                                                        t_high), 4),
                    "low_95": "", "high_95": ""})
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, "loading_rate.csv"), "w",
              newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(out[0]))
        writer.writeheader()
        writer.writerows(out)
    for row in out:
        print(row)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    x = remove_levels(log_t.copy(), subjects, sites)
    y = remove_levels(log_k.copy(), subjects, sites)
    ax.plot(x, y, ".", ms=3, alpha=0.5, color="0.4",
            label="trials (subject and site levels removed)")
    grid = np.linspace(x.min(), x.max(), 2)
    ax.plot(grid, slope * grid, "k-",
            label=f"data: slope {slope:.3f} [{low:.3f}, {high:.3f}]")
    for (name, (g, tau)), colour in zip(PRONY.items(),
                                        ("tab:blue", "tab:orange",
                                         "tab:green", "tab:red")):
        s = model_slope(g, tau, t_low, t_high)
        ax.plot(grid, s * grid, "--", color=colour,
                label=f"model {name}: {s:.4f}")
    ax.set_xlabel("log loading time (displacement / Rate), relative")
    ax.set_ylabel("log stiffness (Total_Stiff), relative")
    ax.set_title("MULTIS: stiffness against loading rate", fontsize=10)
    ax.legend(fontsize=6.5, loc="lower left")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "loading_rate.png"), dpi=120)


if __name__ == "__main__":
    main()
