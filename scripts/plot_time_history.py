#!/usr/bin/python3
"""The picture of an indentation in time (Time/Loading history): left, the
punch's depth and force against time (the end of the ramp and of the hold
marked where the history holds); right, force against depth, whose loop
is the work a cycle dissipates. The title carries the history's measures
(relaxed fraction, residual fraction, work per cycle).

    /usr/bin/python3 scripts/plot_time_history.py RUN_DIR

writes RUN_DIR/time_history.png.
"""
import json, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_manifest  # noqa: E402 (scripts/)


def measures(summary):
    """The history's measures, one phrase each."""
    words = []
    if summary.get("relaxed_fraction") is not None:
        words.append(f"relaxed fraction over the hold "
                     f"{summary['relaxed_fraction']:.3f}")
    if summary.get("residual_fraction") is not None:
        words.append(f"residual fraction after recovery "
                     f"{summary['residual_fraction']:.3f}")
    if summary.get("hysteresis_mJ") is not None:
        works = ", ".join(f"{w:.3g}" for w in summary["hysteresis_mJ"])
        words.append(f"work per cycle {works} mJ")
    return "; ".join(words)


def main(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    history = summary["loading_history"]
    creep = history["kind"] == "creep"
    unit = history["peak_load_unit"]
    # the unloaded start
    times = [0.0] + summary["time_s"]
    depths = [0.0] + summary["depth_mm_vs_time"]
    forces = [0.0] + summary["force_N_vs_time"]

    fig, (ax, loop) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax.plot(times, depths, "o-", ms=3, color="tab:blue", label="depth")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("punch depth (mm)", color="tab:blue")
    ax.set_xlim(left=0)
    twin = ax.twinx()
    twin.plot(times, forces, "s-", ms=3, color="tab:red", label="force")
    twin.set_ylabel("punch force (N)", color="tab:red")
    twin.axhline(0, color="0.7", lw=0.8)
    # both zeros on one line: the fraction below zero alike on both axes
    below = min(0.0, min(forces) / max(forces), min(depths) / max(depths))
    ax.set_ylim(1.05 * below * max(depths), 1.05 * max(depths))
    twin.set_ylim(1.05 * below * max(forces), 1.05 * max(forces))
    for key, label in (("ramp_end_s", "end of ramp"),
                       ("hold_end_s", "end of hold")):
        if key in history:
            ax.axvline(history[key], color="0.6", ls="--", lw=1)
            ax.text(history[key], 0.02 * max(depths), "  " + label,
                    color="0.4", fontsize=8, va="bottom", rotation=90)
    ax.grid(alpha=0.3)

    loop.plot(depths, forces, "o-", ms=3, color="tab:purple")
    loop.axhline(0, color="0.7", lw=0.8)
    loop.set_xlabel("punch depth (mm)")
    loop.set_ylabel("punch force (N)")
    loop.grid(alpha=0.3)

    what = (f"{history['history']} {'force' if creep else 'depth'}, "
            f"peak {history['peak_load']:g} {unit}")
    fig.suptitle(f"{summary['run']}: {what}\n{measures(summary)}",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(run_manifest.record(folder, "time_history.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1])
