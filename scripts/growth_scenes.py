#!/usr/bin/python3
"""Runs the growth scenes from their prm files -- fat injection in the
cheek (deep versus superficial fat) and cellulite in the buttock (young,
aged, after a fasciotomy) -- and writes, into
benchmarks/growth_sensitivity/results/:

  growth_scenes.csv              the metrics of every scene (summary.json)
  cheek_injection.png            DAT versus SAT injection, one colour scale
  buttock_cellulite_aging.png    young versus aged skin
  buttock_cellulite_fasciotomy.png  before versus after the release

    /usr/bin/python3 scripts/growth_scenes.py [--jobs N] [--ranks R]
                                              [--plot-only]

Each run goes to output/<scene>/ (summary.json, growth.csv, elevation.csv,
VTU fields); --plot-only redraws from there.
"""
import argparse, csv, json, os, subprocess, sys, time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SSC = os.path.join(ROOT, "build", "bin", "ssc")
OUTPUT = os.path.join(ROOT, "output")
RESULTS = os.path.join(ROOT, "benchmarks", "growth_sensitivity", "results")
SCENES = ["cheek_injection_dat", "cheek_injection_sat", "buttock_cellulite",
          "buttock_cellulite_aged", "buttock_cellulite_fasciotomy"]
FIGURES = {
    "cheek_injection.png": [("cheek_injection_dat", "0.5 cm3 in DAT"),
                            ("cheek_injection_sat", "0.5 cm3 in SAT")],
    "buttock_cellulite_aging.png": [
        ("buttock_cellulite", "24 cm3 fat growth, young skin"),
        ("buttock_cellulite_aged", "aged skin (modulus x 0.5)")],
    "buttock_cellulite_fasciotomy.png": [
        ("buttock_cellulite", "24 cm3 fat growth"),
        ("buttock_cellulite_fasciotomy", "after fasciotomy (r = 10 mm)")],
}
FIELDS = ["scene", "added_volume_mm3", "volume_change_mm3", "growth_ratio",
          "max_elevation_mm", "mean_elevation_mm", "roughness_mm", "Sa_mm",
          "Svm_mm", "Sz_mm", "dimples",
          "mean_dimple_depth_mm", "max_dimple_depth_mm", "dofs",
          "newton_iterations", "linear_iterations", "wall_time_s"]


def run(scene, ranks):
    prm = os.path.join(ROOT, "prm", scene + ".prm")
    command = [SSC, prm, "-s", f"Run/Output directory={OUTPUT}"]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               # mpirun binds each job's ranks to the first cores: two
               # jobs at once would share one core
               OMPI_MCA_hwloc_base_binding_policy="none")
    start = time.time()
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    print(f"{scene}: exit status {result.returncode} after "
          f"{time.time() - start:.0f} s", flush=True)
    if result.returncode != 0:
        print(result.stderr[-2000:], file=sys.stderr)
    return result.returncode


def row(scene):
    with open(os.path.join(OUTPUT, scene, "summary.json")) as f:
        s = json.load(f)
    return dict(scene=scene, added_volume_mm3=s["added_volume_mm3"],
                volume_change_mm3=f"{s['volume_change_mm3']:.1f}",
                growth_ratio=f"{s['growth']['growth_ratio']:.4f}",
                max_elevation_mm=f"{s['max_elevation_mm']:.4f}",
                mean_elevation_mm=f"{s['mean_elevation_mm']:.4f}",
                roughness_mm=f"{s['roughness_mm']:.4f}",
                Sa_mm=f"{s['surface']['Sa_mm']:.4f}",
                Svm_mm=f"{s['surface']['Svm_mm']:.4f}",
                Sz_mm=f"{s['surface']['Sz_mm']:.4f}",
                dimples=s["dimples"]["count"],
                mean_dimple_depth_mm=f"{s['dimples']['mean_depth_mm']:.4f}",
                max_dimple_depth_mm=f"{s['dimples']['max_depth_mm']:.4f}",
                dofs=s["dofs"],
                newton_iterations=s["solver"]["newton_iterations"],
                linear_iterations=s["solver"]["linear_iterations"],
                wall_time_s=f"{s['timings']['total']:.0f}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--plot-only", action="store_true")
    args = parser.parse_args()
    os.makedirs(RESULTS, exist_ok=True)
    if not args.plot_only:
        with ThreadPoolExecutor(args.jobs) as pool:
            status = list(pool.map(lambda s: run(s, args.ranks), SCENES))
        if any(status):
            sys.exit("some scenes failed")
    rows = [row(s) for s in SCENES]
    with open(os.path.join(RESULTS, "growth_scenes.csv"), "w",
              newline="") as f:
        writer = csv.DictWriter(f, FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    print("| " + " | ".join(FIELDS[:10]) + " |")
    print("|" + "---|" * 10)
    for r in rows:
        print("| " + " | ".join(str(r[k]) for k in FIELDS[:10]) + " |")
    for figure, runs in FIGURES.items():
        subprocess.run(["/usr/bin/python3",
                        os.path.join(ROOT, "scripts", "plot_elevation.py"),
                        os.path.join(RESULTS, figure)] +
                       [f"{os.path.join(OUTPUT, s)}={t}" for s, t in runs],
                       check=True)


if __name__ == "__main__":
    main()
