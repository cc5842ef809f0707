#!/usr/bin/python3
"""What keeping the V-cycle across Newton iterations buys on the main
scene, measured side by side: prm/forearm_indentation.prm as `./ssc.sh
run` runs it (two MPI ranks, the computed error bars on; no fields
written) with the V-cycle rebuilt for every tangent and kept
(`Elasticity/Linear solver/Keep V-cycle = true`) until a solve needs more
than 12 or 20 CG iterations with it, the variants alternating, each
REPEATS times, so that the shared machine's load falls on all alike.

Writes benchmarks/forearm/results/vcycle_reuse.csv (per run: variant,
wall, assembly, solve and error-estimate seconds, Newton and Krylov
iterations, depths) and vcycle_reuse.png.

    /usr/bin/python3 benchmarks/forearm/vcycle_reuse.py [repetitions]
    /usr/bin/python3 benchmarks/forearm/vcycle_reuse.py --plot-only
"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402
from timing_bars import plot_timings, timing_columns  # noqa: E402
from main_scene import NO_PICTURES, SCENE  # noqa: E402
from main_scene import SHIPPED_RANKS as RANKS  # noqa: E402

CSV = os.path.join(HERE, "results", "vcycle_reuse.csv")
KEEP = "Elasticity/Linear solver/Keep V-cycle="
LIMIT = "Elasticity/Linear solver/Refactorization iterations="
VARIANTS = [
    ("rebuilt for every tangent", [KEEP + "false"]),
    ("kept, up to 12 CG iterations", [KEEP + "true", LIMIT + "12"]),
    ("kept, up to 20 CG iterations", [KEEP + "true", LIMIT + "20"]),
]


def measure(repetitions):
    rows = []
    for repetition in range(repetitions):
        for label, overrides in VARIANTS:
            summary, _ = ssc_runner.run_or_exit(
                label, SCENE, NO_PICTURES + overrides, ranks=RANKS, timeout=3600)
            row = dict(variant=label, repetition=repetition + 1,
                       **timing_columns(summary),
                       uncertainty_mm=" ".join(
                           f"{d:.4f}" for d in summary["depth_uncertainty_mm"]))
            print(row, flush=True)
            rows.append(row)
            ssc_runner.write_rows(CSV, rows)


if __name__ == "__main__":
    if sys.argv[1:] != ["--plot-only"]:
        measure(int(sys.argv[1]) if len(sys.argv) > 1 else 2)
    plot_timings(CSV, "variant", f"main scene to 1.8 N on {RANKS} ranks: "
                 "the V-cycle rebuilt or kept")
