#!/usr/bin/python3
"""The picture of an indentation in time (Time/Loading history = ramp and
hold): under a held force (creep) the punch's depth against time, at a
held depth (relaxation) its force against time, the end of the ramp
marked, the relaxed fraction in the title.

    /usr/bin/python3 scripts/plot_time_history.py RUN_DIR

writes RUN_DIR/time_history.png.
"""
import json, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_manifest  # noqa: E402 (scripts/)


def main(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    history = summary["loading_history"]
    creep = history["kind"] == "creep"
    # the unloaded start
    times = [0.0] + summary["time_s"]
    values = [0.0] + (summary["depth_mm_vs_time"] if creep else
                      summary["force_N_vs_time"])
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(times, values, "o-", ms=4, color="tab:blue")
    ax.axvline(history["ramp_time_s"], color="0.6", ls="--", lw=1)
    ax.text(history["ramp_time_s"], 0.05 * max(values), "  end of ramp",
            color="0.4", fontsize=8, va="bottom")
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("time (s)")
    if creep:
        ax.set_ylabel("punch depth (mm)")
        what = f"creep under {history['held_load']:g} N"
    else:
        ax.set_ylabel("punch force (N)")
        what = f"relaxation at {history['held_load']:g} mm"
    ax.set_title(f"{summary['run']}: {what}\nrelaxed fraction over the "
                 f"hold {summary['relaxed_fraction']:.3f}", fontsize=10)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(run_manifest.record(folder, "time_history.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1])
