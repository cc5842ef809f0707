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

SCENE = os.path.join(ssc_runner.ROOT, "prm", "forearm_indentation.prm")
CSV = os.path.join(HERE, "results", "assembly_speed.csv")
OVERRIDES = ["Run/Write fields=false", "Punch/Section=false",
             "Punch/Profile length=0"]
RANKS = 2


def run(label, build):
    """One run of the scene with the build in directory build."""
    env = dict(os.environ, LD_LIBRARY_PATH=build)
    with ssc_runner.scratch() as tmp:
        result = ssc_runner.run(SCENE, OVERRIDES, tmp, "run", ranks=RANKS,
                                ssc=os.path.join(build, "bin", "ssc"),
                                env=env, timeout=3600)
        if not result.ok:
            sys.exit(f"{label}: failed: {result.stderr[-500:]}")
        s = result.summary()
    solver, timings = s["solver"], s["timings"]
    return dict(
        build=label, dofs=s["dofs"], wall_s=round(timings["total"], 1),
        assembly_s=round(timings.get("assembly", 0.), 1),
        solve_s=round(timings.get("solve", 0.), 1),
        estimate_s=round(timings.get("error estimate", 0.), 1),
        newton_iterations=solver["newton_iterations"],
        krylov_iterations=solver["linear_iterations"],
        depths_mm=" ".join(f"{d:.6f}" for d in s["depth_mm"]))


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
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    labels = list(dict.fromkeys(r["build"] for r in rows))
    fig, ax = plt.subplots(figsize=(6, 4))
    for k, label in enumerate(labels):
        runs = sorted((r for r in rows if r["build"] == label),
                      key=lambda r: float(r["wall_s"]))
        median = runs[len(runs) // 2]
        for offset, key, colour in ((-0.25, "wall_s", "0.6"),
                                    (0., "assembly_s", "tab:blue"),
                                    (0.25, "solve_s", "tab:orange")):
            values = [float(r[key]) for r in runs]
            ax.bar(k + offset, float(median[key]), width=0.25, color=colour,
                   label=key.split("_")[0] if k == 0 else None)
            ax.plot([k + offset] * 2, [min(values), max(values)], color="k",
                    lw=1)
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels(labels)
    ax.set_ylabel("time (s)")
    first = rows[0]
    ax.set_title(f"main scene to 1.8 N on {RANKS} ranks ({first['dofs']} "
                 f"DoFs, {first['newton_iterations']} Newton iterations)",
                 fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(CSV.replace(".csv", ".png"), dpi=120)
    print("wrote", CSV.replace(".csv", ".png"))


if __name__ == "__main__":
    if sys.argv[1:] != ["--plot-only"]:
        if not sys.argv[1:]:
            sys.exit(__doc__)
        measure(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 2)
    plot()
