#!/usr/bin/python3
"""How the probe's contact with the skin changes one in vivo trial's answer:
prm/probe_indentation.prm (subject 006's forearm, LA_A moduli, finite
strain, force control to the trial's 3.905 N) with the probe face bonded to
the skin (the identification's forward model), frictionless (ultrasound
gel), and with Coulomb friction of coefficient 0.1 and 0.3. Compared with
the trial's measurements: the probe's travel, its secant stiffness and each
layer's compression under the centre.

Runs ssc on one core into output/benchmarks/probe_contact/<contact> (a
folder that already has a summary.json is read, not run again: --rerun
runs it anyway) and writes benchmarks/identification/results/
probe_contact.csv.

    /usr/bin/python3 benchmarks/identification/probe_contact.py [--rerun]
"""
import argparse, csv, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import ssc_runner  # noqa: E402

PRM = os.path.join(ROOT, "prm", "probe_indentation.prm")
FOLDER = os.path.join(ROOT, "output", "benchmarks", "probe_contact")
CONTACTS = {"bonded": {"Punch/Contact": "bonded"},
            "frictionless": {"Punch/Contact": "frictionless"},
            "friction_0.1": {"Punch/Contact": "friction",
                             "Punch/Friction coefficient": 0.1},
            "friction_0.3": {"Punch/Contact": "friction",
                             "Punch/Friction coefficient": 0.3}}
# subject 006, LA_A (data/multis/indentation_trials.csv, line 2): the
# displacement is TotalStrain x Thickness
MEASURED = {"contact": "measured (MULTIS 006 LA_A)", "force_N": 3.9045,
            "depth_mm": 0.24309 * 22.3093, "skin_strain": 0.2129,
            "fat_strain": 0.2951, "muscle_strain": 0.2342}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rerun", action="store_true")
    args = parser.parse_args()
    rows = [dict(MEASURED,
                 secant_stiffness_N_per_mm=MEASURED["force_N"] /
                 MEASURED["depth_mm"])]
    for name, overrides in CONTACTS.items():
        folder = os.path.join(FOLDER, name)
        if args.rerun or not os.path.exists(
                os.path.join(folder, "summary.json")):
            print(f"{name}: running", flush=True)
            result = ssc_runner.run(
                PRM, dict(overrides, **{"Run/Write fields": "false"}),
                FOLDER, name)
            if not result.ok:
                sys.exit(f"{name}: failed: {result.stderr[-500:]}")
        s = ssc_runner.read_summary(folder)
        strains = s["layer_strain_under_centre_per_step"]
        rows.append({"contact": name, "force_N": s["force_N"][-1],
                     "depth_mm": s["depth_mm"][-1],
                     "secant_stiffness_N_per_mm":
                     s["force_N"][-1] / s["depth_mm"][-1],
                     "skin_strain": strains["skin"][-1],
                     "fat_strain": strains["fat"][-1],
                     "muscle_strain": strains["muscle"][-1],
                     "newton_iterations": s["solver"]["newton_iterations"],
                     "wall_s": s["timings"]["total"]})
    os.makedirs(os.path.join(HERE, "results"), exist_ok=True)
    with open(os.path.join(HERE, "results", "probe_contact.csv"), "w",
              newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[-1].keys()))
        writer.writeheader()
        writer.writerows(rows)
    for r in rows:
        print(f"{r['contact']:28} depth {r['depth_mm']:.3f} mm, secant "
              f"{r['secant_stiffness_N_per_mm']:.3f} N/mm, strains skin "
              f"{r['skin_strain']:.3f} fat {r['fat_strain']:.3f} muscle "
              f"{r['muscle_strain']:.3f}")


if __name__ == "__main__":
    main()
