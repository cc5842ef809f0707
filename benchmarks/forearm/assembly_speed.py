#!/usr/bin/python3
"""What a change of the assembly buys on the main scene, measured side by
side: prm/forearm_indentation.prm as `./ssc.sh run` runs it (two MPI
ranks, the computed error bars on; no fields written), once with a
baseline build and once with this repository's build, alternating, each
REPEATS times, so that the shared machine's load falls on both alike.

The baseline is any earlier build, given as the directory that holds its
bin/ssc and libssc.so, e.g. a worktree of the commit before the change:

    git worktree add /tmp/baseline <commit> && cd /tmp/baseline
    cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
    cmake --build build --target ssc_app

    /usr/bin/python3 benchmarks/forearm/assembly_speed.py BASELINE_BUILD \
        [repetitions]
    /usr/bin/python3 benchmarks/forearm/assembly_speed.py --plot-only

Both builds must give the same Newton and Krylov iterations and the same
depths: the script stops if they do not (a speed-up that changes the
answer is not one). Writes benchmarks/forearm/results/assembly_speed.csv
(per run: build, wall, assembly, solve and error-estimate seconds, Newton
and Krylov iterations, depths) and assembly_speed.png.
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402
from timing_bars import plot_timings, timing_columns  # noqa: E402
from main_scene import NO_PICTURES, SCENE  # noqa: E402
from main_scene import SHIPPED_RANKS as RANKS  # noqa: E402

CSV = os.path.join(HERE, "results", "assembly_speed.csv")


def run(label, build):
    """One run of the scene with the build in directory build."""
    summary, _ = ssc_runner.run_or_exit(
        label, SCENE, NO_PICTURES, ranks=RANKS,
        ssc=os.path.join(build, "bin", "ssc"),
        env=dict(os.environ, LD_LIBRARY_PATH=build), timeout=3600)
    return dict(build=label, **timing_columns(summary))


def measure(baseline, repetitions):
    builds = [("baseline", os.path.abspath(baseline)),
              ("this build", ssc_runner.build_dir())]
    for label, build in builds:
        for needed in ("bin/ssc", "libssc.so"):
            if not os.path.exists(os.path.join(build, needed)):
                sys.exit(f"{label}: no {needed} in {build}")
    rows = []
    for repetition in range(repetitions):
        for label, build in builds:
            row = dict(run(label, build), repetition=repetition + 1)
            print(row, flush=True)
            rows.append(row)
            ssc_runner.write_rows(CSV, rows)
    same = {(r["newton_iterations"], r["krylov_iterations"], r["depths_mm"])
            for r in rows}
    if len(same) != 1:
        sys.exit(f"the builds do not give the same path: {same}")


def plot():
    """Per build the median run's assembly, solve and wall times, whiskers
    over all its runs."""
    with open(CSV) as f:
        first = next(csv.DictReader(f))
    plot_timings(CSV, "build", f"main scene to 1.8 N on {RANKS} ranks "
                 f"({first['dofs']} DoFs)")


if __name__ == "__main__":
    if sys.argv[1:] != ["--plot-only"]:
        if not sys.argv[1:]:
            sys.exit(__doc__)
        measure(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 2)
    plot()
