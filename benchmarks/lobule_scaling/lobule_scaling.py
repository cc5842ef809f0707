#!/usr/bin/python3
"""Time and memory to build 10^3, 10^4 and 10^5 lobules with 30 Lloyd
iterations (clipped Voronoi tessellation with CGAL, one core).

Builds and runs build/benchmarks/lobule_scaling ($SSC_BUILD_DIR if set), writes
benchmarks/lobule_scaling/results/lobule_scaling.csv and .png.

    /usr/bin/python3 benchmarks/lobule_scaling/lobule_scaling.py [--max 100000]
"""
import csv, io, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

BUILD = ssc_runner.build_dir()
OUT = os.path.join(HERE, "results")


def main():
    largest = "100000"
    if "--max" in sys.argv:
        largest = sys.argv[sys.argv.index("--max") + 1]
    subprocess.run(["cmake", "--build", BUILD, "--target", "lobule_scaling"],
                   check=True, stdout=subprocess.DEVNULL)
    done = subprocess.run([os.path.join(BUILD, "benchmarks", "lobule_scaling"),
                           largest], check=True, capture_output=True,
                          text=True)
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, "lobule_scaling.csv"), "w") as f:
        f.write(done.stdout)
    rows = list(csv.DictReader(io.StringIO(done.stdout)))
    print(done.stdout, end="")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = [int(r["lobules"]) for r in rows]
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].loglog(n, [float(r["seconds_lloyd"]) for r in rows], "o-",
                 label="seeds + 30 Lloyd iterations")
    ax[0].loglog(n, [float(r["seconds_final_with_faces"]) for r in rows],
                 "s-", label="final tessellation with faces")
    ax[0].loglog([1e4], [5], "r*", markersize=12, label="target: 10^4 in 5 s")
    ax[0].loglog(n, [float(rows[0]["seconds_lloyd"]) * k / n[0] for k in n],
                 "k:", label="linear")
    ax[0].set_xlabel("lobules")
    ax[0].set_ylabel("wall time [s] (1 core)")
    ax[0].legend(fontsize=8)
    ax[0].grid(True, which="both", alpha=0.3)
    ax[1].semilogx(n, [float(r["peak_memory_MB"]) for r in rows], "o-")
    ax[1].set_xlabel("lobules")
    ax[1].set_ylabel("peak resident memory [MB]")
    ax[1].grid(True, which="both", alpha=0.3)
    fig.suptitle("Lloyd-relaxed clipped Voronoi tessellation (CGAL Delaunay_3 "
                 "with mirror seeds)")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "lobule_scaling.png"), dpi=110)


if __name__ == "__main__":
    main()
