#!/usr/bin/python3
"""Large deformation of the forearm indentation (prm/forearm_indentation_linear.prm
with its microstructure) up to 1.8 N: linear versus corotational versus
neo-Hookean layers, bonded and frictionless punch, force control.

Every law uses the Q1 mixed formulation by default (mean dilatation at
finite strain; the enhanced modes of the scene's default are for the
linear law only) on the scene's mesh with fewer refinements towards the
punch edge (Mesh/Region of interest/Local refinements, default 1: 59k
DoFs; prm/forearm_indentation_finite_strain.prm is the --degree 2
--refinements 0 set-up). The finite-strain
runs use tension-field septa and tension-only ligaments
(Embedded/Septa/Tension field, Embedded/Ligaments/Tension only):
compressed septa wrinkle and compressed ligaments go slack; and the skin
touches the punch's rounded edge (Punch/Edge contact) instead of passing
through it. Records per load step the depth, Newton iterations, CG
iterations, load cuts and wall time on 2 MPI ranks.

Writes benchmarks/finite_strain_solver/results/large_deformation.csv and .png.

--formulation displacement runs every law with the plain Q1 displacement
formulation instead (large_deformation_displacement.csv and .png): it
locks at nu = 0.49 (15-17 % shallower) and so reaches 1.8 N at about
10 mm, before the depth of about 11 mm where the mixed tangent turns
indefinite on this mesh (benchmarks/finite_strain_solver/README.md).

--degree 2 runs Q2 elements (large_deformation_q2.csv and .png; with the
mixed formulation Q2 with the mean dilatation, Q2-P0, which is inf-sup
stable); use it with --refinements 0 (257k DoFs). Bonded, the Q2 runs
pass that depth without negative curvature (benchmarks/finite_strain_solver/
README.md).

--globalisation chooses Nonlinear solver/Globalisation (default hybrid:
the energy line search, and trust-region steps where it finds no
decrease).

--laws and --contacts run a subset; its rows replace those of the same law
and contact in the CSV, the others stay. --ranks sets the MPI ranks (2).
The runs' folders, with their log.txt, stay in output/large_deformation*/
(SSC_BUILD_DIR chooses the build, as for ssc.sh).

    /usr/bin/python3 benchmarks/finite_strain_solver/large_deformation.py
        [--refinements N] [--formulation mixed|mean dilatation|displacement]
        [--degree 1|2] [--ranks N]
        [--globalisation "line search"|"trust region"|hybrid]
        [--laws LAW ...] [--contacts CONTACT ...] [--plot-only]
"""
import argparse, csv, os, re, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

ROOT = ssc_runner.ROOT
PRM = os.path.join(ROOT, "prm", "forearm_indentation_linear.prm")
OUT = os.path.join(HERE, "results")
LAYERS = ["skin", "SAT", "SM", "DAT", "deep"]
LAWS = ["linear", "corotational", "neo-Hookean"]
CONTACTS = ["bonded", "frictionless"]
FIELDS = ["law", "contact", "dofs", "step", "force_N", "depth_mm",
          "newton_iterations", "linear_iterations", "load_cuts",
          "wall_time_s", "total_wall_time_s", "status"]


def run(law, contact, refinements, formulation, degree, ranks, globalisation,
        folder):
    name = f"{law}_{contact}".replace("-", "_")
    overrides = {
        "Run/Write fields": "false", "Punch/Section": "false",
        "Punch/Contact": contact, "Elasticity/Formulation": formulation,
        "Elasticity/Degree": str(degree),
        "Nonlinear solver/Globalisation": globalisation,
        "Mesh/Region of interest/Local refinements": str(refinements)}
    for layer in LAYERS:
        overrides[f"Layer stack/{layer}/Material model"] = law
    if law != "linear":
        overrides["Embedded/Septa/Tension field"] = "true"
        overrides["Embedded/Ligaments/Tension only"] = "true"
        overrides["Punch/Edge contact"] = "true"
    # a guard against a hang, not a limit on a slow run: a Q2 run takes
    # about an hour on this machine; mpirun even for one rank, its ranks
    # not bound to cores
    result = ssc_runner.run(PRM, overrides, folder, name, ranks=ranks,
                            timeout=3600 * degree**2 * 2 // ranks)
    total = result.wall_s
    if result.returncode != 0:
        lines = [l for l in result.stderr.splitlines() if "error" in l]
        message = lines[-1] if lines else f"exit status {result.returncode}"
        print(f"{law}, {contact}: {message}", flush=True)
        return stopped_run_rows(law, contact, result.stdout, message, total)
    dofs = next(line.split(":")[1].split("(")[0].strip()
                for line in result.stdout.splitlines()
                if line.startswith("Degrees of freedom"))
    steps = ssc_runner.read_table(result.folder)
    rows = []
    for s in steps:
        rows.append(dict(law=law, contact=contact, dofs=dofs,
                         step=s["step"], force_N=s["force_N"],
                         depth_mm=s["depth_mm"],
                         newton_iterations=s.get("newton_iterations", 0),
                         linear_iterations=s.get("linear_iterations", 0),
                         load_cuts=s.get("load_cuts", 0),
                         wall_time_s=s.get("wall_time_s", ""),
                         total_wall_time_s=f"{total:.1f}",
                         status="converged"))
    print(f"{law}, {contact}: {dofs} DoFs, depth at 1.8 N "
          f"{rows[-1]['depth_mm']} mm, {total:.0f} s", flush=True)
    return rows


def stopped_run_rows(law, contact, log, message, total):
    """The load steps a stopped run converged (from its log) and a last
    row with the error."""
    step_line = re.compile(
        r"Load step (\d+) of \d+: force (\S+) N, depth (\S+) mm "
        r"\(\d+ increments, (\d+) cut, (\d+) Newton iterations, "
        r"(\d+) CG iterations\)")
    dofs = next((line.split(":")[1].split("(")[0].strip()
                 for line in log.splitlines()
                 if line.startswith("Degrees of freedom")), "")
    rows = []
    for m in step_line.finditer(log):
        rows.append(dict(law=law, contact=contact, dofs=dofs, step=m[1],
                         force_N=m[2], depth_mm=m[3], load_cuts=m[4],
                         newton_iterations=m[5], linear_iterations=m[6],
                         total_wall_time_s=f"{total:.1f}",
                         status="converged"))
    rows.append(dict(law=law, contact=contact, dofs=dofs, step="",
                     total_wall_time_s=f"{total:.1f}", status=message))
    return rows


def plot(rows, path, formulation, degree):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(12, 5))
    styles = {"linear": "k--", "corotational": "bs-", "neo-Hookean": "ro-"}
    for a, contact in zip(ax, CONTACTS):
        for law in LAWS:
            rs = [r for r in rows if r["law"] == law and
                  r["contact"] == contact and r["status"] == "converged"]
            failed = [r for r in rows if r["law"] == law and
                      r["contact"] == contact and r["status"] != "converged"]
            for r in failed:
                words = r["status"].split("failed at load ")
                if len(words) > 1:
                    where = f"stops at {float(words[1].split()[0]):.3f} N"
                elif r["status"].startswith("not finished"):
                    where = "not finished"
                else:
                    where = "failed"
                a.plot([], [], " ", label=f"{law}: {where}")
            if not rs:
                continue
            a.plot([0] + [float(r["depth_mm"]) for r in rs],
                   [0] + [float(r["force_N"]) for r in rs], styles[law],
                   label=law)
        a.set_title(f"{contact} punch")
        a.set_xlabel("depth [mm]")
        a.set_ylabel("force [N]")
        a.grid(True, alpha=0.3)
        a.legend()
    dofs = rows[0]["dofs"] if rows else "?"
    fig.suptitle("Forearm indentation with septa and ligaments, "
                 f"Q{degree} {formulation}, {dofs} DoFs: linear vs "
                 "corotational vs neo-Hookean")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--refinements", type=int, default=1)
    parser.add_argument("--formulation", choices=["mixed", "mean dilatation", "displacement"],
                        default="mixed")
    parser.add_argument("--degree", type=int, choices=[1, 2], default=1)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--globalisation", default="hybrid",
                        choices=["line search", "trust region", "hybrid"])
    parser.add_argument("--laws", nargs="+", choices=LAWS, default=LAWS)
    parser.add_argument("--contacts", nargs="+", choices=CONTACTS,
                        default=CONTACTS)
    parser.add_argument("--plot-only", action="store_true")
    args = parser.parse_args()
    stem = ("large_deformation" +
            ("" if args.formulation == "mixed" else "_" + args.formulation) +
            ("" if args.degree == 1 else f"_q{args.degree}"))
    csv_path = os.path.join(OUT, stem + ".csv")
    os.makedirs(OUT, exist_ok=True)
    if not args.plot_only:
        folder = os.path.join(ROOT, "output", stem)
        os.makedirs(folder, exist_ok=True)
        new_rows = {}
        for contact in args.contacts:
            for law in args.laws:
                new_rows[(law, contact)] = run(law, contact, args.refinements,
                                               args.formulation, args.degree,
                                               args.ranks, args.globalisation,
                                               folder)
        # read only now: another subset may have been run meanwhile
        rows = {}
        if os.path.exists(csv_path):
            with open(csv_path) as f:
                for r in csv.DictReader(f):
                    rows.setdefault((r["law"], r["contact"]), []).append(r)
        rows.update(new_rows)
        with open(csv_path, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=FIELDS)
            writer.writeheader()
            for contact in CONTACTS:
                for law in LAWS:
                    writer.writerows(rows.get((law, contact), []))
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    plot(rows, os.path.join(OUT, stem + ".png"), args.formulation,
         args.degree)


if __name__ == "__main__":
    main()
