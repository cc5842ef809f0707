#!/usr/bin/python3
"""Speed versus error of the frictionless punch against Sneddon.

Runs build/bin/ssc on benchmarks/punch_sneddon.prm for Q1 and Q2, the
displacement and the mixed (B-bar) formulation, nu = 0.3 and 0.49, over four
levels of refinement towards the punch edge; writes
benchmarks/results/speed_vs_error.csv and .png.

    /usr/bin/python3 benchmarks/speed_vs_error.py [--quick]
"""
import csv, json, os, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SSC = os.path.join(ROOT, "build", "bin", "ssc")
PRM = os.path.join(ROOT, "benchmarks", "punch_sneddon.prm")
OUT = os.path.join(ROOT, "benchmarks", "results")
# levels = local refinements towards the punch edge (the base cell is 40 mm)
# (Q2 starts at 6: the fitted punch edge needs 2.5 mm cells or smaller)
LEVELS = {1: [9, 10, 11, 12], 2: [6, 7, 8, 9]}
SKIP_AFTER_S = 60  # a configuration stops once one of its runs takes longer
FIELDS = ["nu", "degree", "formulation", "level", "dofs", "cells",
          "cg_iterations", "stiffness_N_per_mm", "sneddon_N_per_mm",
          "relative_error", "t_mesh", "t_setup", "t_assembly", "t_solve",
          "t_output", "t_total", "memory_MB", "dofs_per_second"]


def run(nu, degree, formulation, level, folder):
    name = f"nu{nu}_q{degree}_{formulation}_l{level}"
    args = [SSC, PRM, "-s", f"Run/Output directory={folder}",
            "-s", f"Run/Name={name}",
            "-s", f"Layer stack/block/Poisson's ratio={nu}",
            "-s", f"Elasticity/Degree={degree}",
            "-s", f"Elasticity/Formulation={formulation}",
            "-s", f"Mesh/Region of interest/Local refinements={level}"]
    done = subprocess.run(args, capture_output=True, text=True, timeout=900)
    if done.returncode != 0:
        print(f"{name} failed:\n{done.stderr}", flush=True)
        return None
    with open(os.path.join(folder, name, "summary.json")) as f:
        s = json.load(f)
    t = s["timings"]
    k, ref = s["stiffness_N_per_mm"], s["half_space_stiffness_N_per_mm"]
    return dict(nu=nu, degree=degree, formulation=formulation, level=level,
                dofs=s["dofs"], cells=s["cells"],
                cg_iterations=s["solver"]["linear_iterations"],
                stiffness_N_per_mm=k, sneddon_N_per_mm=ref,
                relative_error=k / ref - 1, t_mesh=t["mesh"],
                t_setup=t["setup"], t_assembly=t["assembly"],
                t_solve=t["solve"], t_output=t["output"], t_total=t["total"],
                memory_MB=s["memory_MB"],
                dofs_per_second=s["dofs"] / t["total"])


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    keys = sorted({(r["nu"], r["degree"], r["formulation"]) for r in rows})
    for key in keys:
        rs = [r for r in rows if (r["nu"], r["degree"], r["formulation"]) == key]
        label = f"Q{key[1]} {key[2]} nu={key[0]}"
        dofs = [r["dofs"] for r in rs]
        err = [abs(r["relative_error"]) for r in rs]
        ax[0, 0].loglog(dofs, err, "o-", label=label)
        ax[0, 1].loglog([r["t_total"] for r in rs], err, "o-", label=label)
        ax[1, 0].semilogx(dofs, [r["cg_iterations"] for r in rs], "o-",
                          label=label)
        ax[1, 1].loglog(dofs, [r["t_total"] for r in rs], "o-", label=label)
    for a, (x, y) in zip(ax.flat, [("DoFs", "|F/F_Sneddon - 1|"),
                                   ("wall time [s]", "|F/F_Sneddon - 1|"),
                                   ("DoFs", "CG iterations"),
                                   ("DoFs", "wall time [s]")]):
        a.set_xlabel(x)
        a.set_ylabel(y)
        a.grid(True, which="both", alpha=0.3)
    ax[0, 0].legend(fontsize=7)
    fig.suptitle("Frictionless punch on a deep block vs Sneddon (1 core)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    quick = "--quick" in sys.argv
    os.makedirs(OUT, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for nu in ([0.3] if quick else [0.3, 0.49]):
            for degree in (1, 2):
                for formulation in ("displacement", "mixed"):
                    for level in LEVELS[degree][: 2 if quick else 4]:
                        if rows and rows[-1]["t_total"] > SKIP_AFTER_S and \
                                rows[-1]["degree"] == degree and \
                                rows[-1]["formulation"] == formulation:
                            break
                        r = run(nu, degree, formulation, level, folder)
                        if r is None:
                            break
                        rows.append(r)
                        print(f"nu={nu} Q{degree} {formulation:12s} "
                              f"level {level}: {r['dofs']:8d} DoFs, "
                              f"{r['cg_iterations']:4d} CG, error "
                              f"{100 * r['relative_error']:+6.2f} %, "
                              f"{r['t_total']:6.1f} s", flush=True)
    with open(os.path.join(OUT, "speed_vs_error.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(OUT, "speed_vs_error.png"))


if __name__ == "__main__":
    main()
