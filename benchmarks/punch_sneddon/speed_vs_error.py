#!/usr/bin/python3
"""Speed versus error of the frictionless punch against Sneddon.

Runs build/bin/ssc on punch_sneddon.prm (in this folder) for Q1 and Q2, the
displacement and the mixed (B-bar) formulation, nu = 0.3 and 0.49, over four
levels of refinement towards the punch edge; writes
benchmarks/punch_sneddon/results/speed_vs_error.csv and .png.

    /usr/bin/python3 benchmarks/punch_sneddon/speed_vs_error.py
        [--quick | --plot-only]

--plot-only redraws the PNG from the last CSV.
"""
import csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

PRM = os.path.join(HERE, "punch_sneddon.prm")
OUT = os.path.join(HERE, "results")
# levels = local refinements towards the punch edge (the base cell is 160 mm)
# (Q2 starts at 6: the fitted punch edge needs 2.5 mm cells or smaller)
LEVELS = {1: [9, 10, 11, 12], 2: [6, 7, 8, 9]}
SKIP_AFTER_S = 60  # a configuration stops once one of its runs takes longer
FIELDS = ["nu", "degree", "formulation", "amg", "level", "dofs", "cells",
          "cg_iterations", "stiffness_N_per_mm", "sneddon_N_per_mm",
          "relative_error", "t_mesh", "t_setup", "t_assembly", "t_solve",
          "t_output", "t_total", "memory_MB", "memory_at_start_MB",
          "kB_per_dof", "kB_per_dof_model", "dofs_per_second"]
# (nu, degree, formulation, AMG prolongator): the smoothed-aggregation AMG is
# the default; plain aggregation trades iterations for memory.
CONFIGURATIONS = [(nu, degree, formulation, "smoothed")
                  for nu in (0.3, 0.49) for degree in (1, 2)
                  for formulation in ("displacement", "mixed")] + \
                 [(0.49, 1, "mixed", "plain")]


def run(nu, degree, formulation, amg, level, folder):
    name = f"nu{nu}_q{degree}_{formulation}_{amg}_l{level}"
    overrides = {"Layer stack/block/Poisson's ratio": nu,
                 "Elasticity/Degree": degree,
                 "Elasticity/Formulation": formulation,
                 "Elasticity/Linear solver/Smoothed aggregation":
                 "true" if amg == "smoothed" else "false",
                 "Mesh/Region of interest/Local refinements": level}
    done = ssc_runner.run(PRM, overrides, folder, name, timeout=900)
    if not done.ok:
        print(f"{name} failed:\n{done.stderr}", flush=True)
        return None
    s = done.summary()
    t = s["timings"]
    k, ref = s["stiffness_N_per_mm"], s["half_space_stiffness_N_per_mm"]
    mem, mem0 = s["memory_MB"], s["memory_at_start_MB"]
    return dict(nu=nu, degree=degree, formulation=formulation, amg=amg,
                level=level,
                dofs=s["dofs"], cells=s["cells"],
                cg_iterations=s["solver"]["linear_iterations"],
                stiffness_N_per_mm=k, sneddon_N_per_mm=ref,
                relative_error=k / ref - 1, t_mesh=t["mesh"],
                t_setup=t["setup"], t_assembly=t["assembly"],
                t_solve=t["solve"], t_output=t["output"], t_total=t["total"],
                memory_MB=mem, memory_at_start_MB=mem0,
                kB_per_dof=1024 * mem / s["dofs"],
                kB_per_dof_model=1024 * (mem - mem0) / s["dofs"],
                dofs_per_second=s["dofs"] / t["total"])


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    for k in sorted({key(r) for r in rows}):
        rs = [r for r in rows if key(r) == k]
        label = f"Q{int(k[1])} {k[2]} nu={k[0]}" + \
            ("" if k[3] == "smoothed" else " plain AMG")
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


def key(r):
    return (r["nu"], r["degree"], r["formulation"], r["amg"])


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for name in FIELDS:
            if name not in ("formulation", "amg"):
                r[name] = float(r[name])
    return rows


def main():
    csv_path = os.path.join(OUT, "speed_vs_error.csv")
    if "--plot-only" in sys.argv:
        plot(read_csv(csv_path), os.path.join(OUT, "speed_vs_error.png"))
        return
    quick = "--quick" in sys.argv
    os.makedirs(OUT, exist_ok=True)
    rows = []
    with ssc_runner.scratch() as folder:
        for (nu, degree, formulation, amg) in CONFIGURATIONS:
            if quick and nu != 0.3:
                continue
            for level in LEVELS[degree][: 2 if quick else 4]:
                if rows and rows[-1]["t_total"] > SKIP_AFTER_S and \
                        key(rows[-1]) == (nu, degree, formulation, amg):
                    break
                r = run(nu, degree, formulation, amg, level, folder)
                if r is None:
                    break
                rows.append(r)
                print(f"nu={nu} Q{degree} {formulation:12s} {amg:8s} "
                      f"level {level}: {r['dofs']:8d} DoFs, "
                      f"{r['cg_iterations']:4d} CG, error "
                      f"{100 * r['relative_error']:+6.2f} %, "
                      f"{r['t_total']:6.1f} s, "
                      f"{r['kB_per_dof']:.2f} kB/DoF", flush=True)
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(OUT, "speed_vs_error.png"))


if __name__ == "__main__":
    main()
