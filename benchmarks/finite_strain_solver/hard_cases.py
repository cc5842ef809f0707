#!/usr/bin/python3
"""Hard-case suite of the finite-strain solver: each case runs the coarse
forearm indentation of hard_cases.prm (in this folder; neo-Hookean layers
unless the case says otherwise, mean dilatation, tension-field septa,
tension-only ligaments, edge contact, force control to 1.8 N, Newton's
method with the default globalisation: the energy line search,
trust-region steps where it finds no decrease) with a few overrides and
reports whether it converged -- or the clear error it stopped with -- and
the cost: load steps, Newton and CG iterations, load cuts, wall time on one
core.

Writes benchmarks/finite_strain_solver/results/hard_cases.csv and prints a
Markdown table.

    /usr/bin/python3 benchmarks/finite_strain_solver/hard_cases.py [--jobs N]
        [--cases I ...] [--set KEY=VALUE ...] [--csv NAME] [--timeout S]

(--jobs 2 runs two cases at a time on the 2 cores: their wall times then
include the sharing. --cases runs the cases of these indices (from 0, in
the order of CASES) and replaces their rows in the CSV, the others stay.
SSC_BUILD_DIR chooses the build, as for ssc.sh. The run folders, with
their log.txt, stay in output/hard_cases/caseI/. --set adds an entry to
every case, e.g. "Elasticity/Linear solver/Preconditioner=cholesky", and
--csv names the results file for such a variant.)
"""
import argparse, concurrent.futures, csv, os, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

ROOT = ssc_runner.ROOT
PRM = os.path.join(HERE, "hard_cases.prm")
OUT = os.path.join(HERE, "results")
LAYERS = ["skin", "SAT", "SM", "DAT", "deep"]
TIMEOUT = 3600  # s: a guard against a hang, far above any case's time


def every_layer(name, value):
    return {f"Layer stack/{l}/{name}": value for l in LAYERS}


# Q2 elements with the mean dilatation, no refinement towards the punch edge
# (30k DoFs)
Q2 = {"Elasticity/Degree": "2", "Elasticity/Formulation": "mean dilatation",
      "Mesh/Region of interest/Local refinements": "0"}

# soft layers above the muscle: skin 1.2 + SAT 2.5 + SM 0.4 + DAT 2 = 6.1 mm
CASES = [
    ("reference: bonded, 1.8 N", {}),
    ("frictionless punch, 1.8 N", {"Punch/Contact": "frictionless"}),
    ("frictionless punch without the edge contact",
     {"Punch/Contact": "frictionless", "Punch/Edge contact": "false"}),
    ("corotational, bonded, 1.8 N", every_layer("Material model",
                                                "corotational")),
    ("corotational, frictionless, 1.8 N",
     {**every_layer("Material model", "corotational"),
      "Punch/Contact": "frictionless"}),
    ("nu = 0.4999 in every layer", every_layer("Poisson's ratio", "0.4999")),
    ("stiffness contrast 100:1 (skin E = 100 x fat)",
     {"Layer stack/skin/Young's modulus": "0.1"}),
    ("stiffness contrast 1000:1 (skin E = 1000 x fat)",
     {"Layer stack/skin/Young's modulus": "1"}),
    ("SM 0.05 mm thick (3 mm cells: aspect 60)",
     {"Layer stack/SM/Thickness": "0.05"}),
    ("depth 3.05 mm = 50 % of the soft layers (displacement control)",
     {"Punch/Control": "displacement", "Punch/Depth": "3.05",
      "Punch/Load steps": "2"}),
    ("one load step of 1.8 N (first increment the whole load)",
     {"Punch/Forces": "1.8", "Nonlinear solver/Initial steps": "1"}),
    ("septa carrying compression (no tension field)",
     {"Embedded/Septa/Tension field": "false"}),
    ("Q2 elements (Q2-P0), bonded", Q2),
    ("Q2 elements (Q2-P0), frictionless",
     {**Q2, "Punch/Contact": "frictionless"}),
    ("nu = 0.4999 in every layer, Q2 elements",
     {**Q2, **every_layer("Poisson's ratio", "0.4999")}),
    ("Q2 elements, frictionless, one refinement towards the punch edge",
     {**Q2, "Punch/Contact": "frictionless",
      "Mesh/Region of interest/Local refinements": "1"}),
    ("one load step of 1.8 N, line search and continuation only",
     {"Punch/Forces": "1.8", "Nonlinear solver/Initial steps": "1",
      "Nonlinear solver/Globalisation": "line search"}),
]
FIELDS = ["case", "converged", "message", "force_N", "depth_mm",
          "newton_iterations", "linear_iterations", "load_cuts",
          "wall_time_s", "dofs"]


def run(label, overrides, folder, index, timeout):
    name = f"case{index}"
    start = time.time()
    try:
        result = ssc_runner.run(PRM, overrides, folder, name,
                                timeout=timeout)
        status, stderr = result.returncode, result.stderr
    except subprocess.TimeoutExpired:
        status, stderr = -1, f"timeout after {timeout} s"
    wall = time.time() - start
    row = dict(case=label, converged="yes" if status == 0 else "no",
               message="", wall_time_s=f"{wall:.1f}")
    if status != 0:
        lines = [l for l in stderr.splitlines() if l.strip()]
        row["message"] = lines[-1] if lines else f"exit status {status}"
        return row
    s = result.summary()
    solver = s.get("solver", {})
    row.update(force_N=s["force_N"][-1] if isinstance(s["force_N"], list)
               else s["force_N"],
               depth_mm=f"{(s['depth_mm'][-1] if isinstance(s['depth_mm'], list) else s['depth_mm']):.4f}",
               newton_iterations=solver.get("newton_iterations", ""),
               linear_iterations=solver.get("linear_iterations", ""),
               load_cuts=sum(solver.get("load_cuts_per_step", [])),
               dofs=s["dofs"])
    return row


def merged_rows(new_rows, path):
    """The CSV's rows in the order of CASES: the new ones, and the old ones
    of the cases not run now."""
    by_case = {}
    if os.path.exists(path):
        with open(path, newline="") as f:
            by_case = {r["case"]: r for r in csv.DictReader(f)}
    by_case.update({r["case"]: r for r in new_rows})
    return [by_case[label] for label, _ in CASES if label in by_case]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--cases", type=int, nargs="+",
                        choices=range(len(CASES)),
                        default=list(range(len(CASES))))
    parser.add_argument("--set", nargs="+", default=[], metavar="KEY=VALUE",
                        help="entries added to every case")
    parser.add_argument("--csv", default="hard_cases.csv")
    parser.add_argument("--timeout", type=float, default=TIMEOUT)
    args = parser.parse_args()
    common = dict(entry.split("=", 1) for entry in args.set)
    # a variant's run folders must not overwrite the default's
    variant = os.path.splitext(args.csv)[0]
    os.makedirs(OUT, exist_ok=True)
    # the run folders, with their logs, stay for a look at what a case did
    folder = os.path.join(ROOT, "output", variant)
    os.makedirs(folder, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(run, CASES[index][0],
                               {**common, **CASES[index][1]}, folder, index,
                               args.timeout)
                   for index in args.cases]
        new_rows = []
        for future in futures:
            new_rows.append(future.result())
            print(new_rows[-1], flush=True)
    path = os.path.join(OUT, args.csv)
    rows = merged_rows(new_rows, path)
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    print("| case | converged | force [N] | depth [mm] | Newton | CG | "
          "cuts | wall [s] |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['case']} | {r['converged']}"
              f"{' (' + r['message'] + ')' if r['message'] else ''} | "
              f"{r.get('force_N', '')} | {r.get('depth_mm', '')} | "
              f"{r.get('newton_iterations', '')} | "
              f"{r.get('linear_iterations', '')} | {r.get('load_cuts', '')}"
              f" | {r['wall_time_s']} |")


if __name__ == "__main__":
    main()
