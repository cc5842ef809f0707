#!/usr/bin/python3
"""The error of the fixed time steps of the loading histories beyond ramp
and hold: prm/forearm_creep_recovery.prm (1 N ramped, held 10 minutes,
removed over 1 s, 10 minutes of recovery) and prm/forearm_cyclic.prm (two
force cycles 0 -> 1 N -> 0 of 2 minutes), each as shipped and with every
step halved (twice the steps per segment, hold and recovery steps growing
by the square root of the shipped ratio: every other end time is a shipped
one). Compared at the shared times: the depth, and the history's measures
(relaxed and residual fraction; the work per cycle, whose trapezoidal
rule over the steps is part of what the steps decide).

Writes benchmarks/forearm/results/history_steps.csv (one row per run).

    /usr/bin/python3 benchmarks/forearm/history_steps.py
"""
import math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

RESULTS = os.path.join(HERE, "results", "history_steps.csv")
FOLDER = os.path.join(ROOT, "output", "benchmarks", "history_steps")

RECOVERY = (os.path.join(ROOT, "prm", "forearm_creep_recovery.prm"),
            {"Time/Ramp steps": 8, "Time/Hold steps": 24,
             "Time/Unload steps": 8, "Time/Recovery steps": 24,
             "Time/Hold step growth": math.sqrt(1.3)})
CYCLIC = (os.path.join(ROOT, "prm", "forearm_cyclic.prm"),
          {"Time/Steps per cycle": 16})


def main():
    rows = []
    for name, (prm, halved) in (("creep recovery", RECOVERY),
                                ("cyclic", CYCLIC)):
        runs = {}
        for label, overrides in (("shipped", {}), ("halved", halved)):
            overrides = dict(overrides, **{"Run/Write fields": "false"})
            run = ssc_runner.run(prm, overrides, output_dir=FOLDER,
                                 name=f"{name.replace(' ', '_')}_{label}",
                                 ranks=2, timeout=3600, check=True)
            runs[label] = (run, run.summary())
            print(f"{name}, {label}: {run.wall_s:.0f} s", flush=True)
        shipped = dict(zip((round(t, 6) for t in runs["shipped"][1]["time_s"]),
                           runs["shipped"][1]["depth_mm"]))
        worst = 0.0
        for t, d in zip(runs["halved"][1]["time_s"],
                        runs["halved"][1]["depth_mm"]):
            if round(t, 6) in shipped:
                worst = max(worst, abs(shipped[round(t, 6)] / d - 1))
        for label, (run, s) in runs.items():
            rows.append({
                "history": name, "steps": label,
                "n_steps": len(s["time_s"]), "wall_s": round(run.wall_s, 1),
                "newton_iterations": s["solver"]["newton_iterations"],
                "final_depth_mm": s["depth_mm"][-1],
                "relaxed_fraction": s["relaxed_fraction"],
                "residual_fraction": s["residual_fraction"],
                "hysteresis_mJ": " ".join(f"{w:.6g}" for w in
                                          s["hysteresis_mJ"] or []),
                "largest_depth_difference_at_shared_times":
                    worst if label == "halved" else ""})
        print(f"{name}: shipped and halved steps differ by at most "
              f"{100 * worst:.4f} % in depth", flush=True)
    ssc_runner.write_rows(RESULTS, rows)


if __name__ == "__main__":
    main()
