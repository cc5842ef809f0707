#!/usr/bin/python3
"""ssc against CalculiX on the layered bonded punch, at equal error against
an independent reference, run side by side in this script on this machine.

The problem (benchmarks/common/calculix_punch.py has the details):
prm/punch.prm's five layers (skin, SAT, SM, DAT, muscle; Herlin's moduli,
one nu) in a cylinder of radius 30 mm on a fixed base and a fixed side, a
bonded rigid punch of radius 2.5 mm pressed 0.5 mm, linear elasticity; the
stiffness K = F / d. The problem is axisymmetric, so

- the reference is CalculiX's axisymmetric CAX8R on a (r, z) mesh graded
  to 1e-5 mm at the punch edge, converged by its own refinement sequence
  (calculix_punch.reference_stiffness; about 1e-5 relative, far below the
  0.3 % asked of the 3D runs);
- the peer is CalculiX 3D: C3D20R on an O-grid of the cylinder
  (calculix_punch.peer_3d), SPOOLES direct solver, one thread;
- ssc runs prm/punch.prm with Mesh/Layout = o-grid, Outer boundary =
  circle, Elasticity/Sides = fixed, no local refinement, the sparse
  Cholesky factor as CG's preconditioner (one solve to 1e-10 relative
  residual; the factor makes it one or two iterations), Q2 mixed
  (isoparametric on the o-grid) and Q1 enhanced, over meshes from coarse
  to fine.

Every run is one process on one core; wall time and peak resident memory
of that process (os.wait4). The runs of the two codes alternate so that the
machine's load affects both alike. Writes benchmarks/peer_calculix/results/
peer_calculix.csv and .png (relative error against wall time) and prints,
per code, the fastest run within 1 % and within 0.3 %.

    /usr/bin/python3 benchmarks/peer_calculix/peer_calculix.py
        [--nu 0.3 0.49 0.4999] [--plot-only]
"""
import argparse, csv, os, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import calculix_punch as cp  # noqa: E402
import ssc_runner  # noqa: E402

ROOT = ssc_runner.ROOT
PRM = os.path.join(ROOT, "prm", "punch.prm")
OUT = os.path.join(HERE, "results")
LAYERS = ["skin", "SAT", "SM", "DAT", "deep"]
FIELDS = ["code", "discretisation", "nu", "mesh", "dofs", "K_N_per_mm",
          "relative_error", "wall_s", "memory_MB"]

# ssc o-grid meshes: (degree, formulation, cells around, edge size, grading)
SSC_MESHES = [(2, "mixed", 8, 0.8, 2.0), (2, "mixed", 8, 0.3, 1.8),
              (2, "mixed", 12, 0.6, 2.0), (2, "mixed", 8, 0.1, 1.6),
              (2, "mixed", 12, 0.2, 1.6), (2, "mixed", 12, 0.1, 1.6),
              (2, "mixed", 16, 0.05, 1.5),
              (1, "enhanced", 16, 0.2, 1.5), (1, "enhanced", 32, 0.1, 1.4)]


def run_ssc(nu, degree, formulation, n, edge, grading, folder, reference):
    name = f"ssc_q{degree}{formulation[0]}_n{n}_h{edge}_q{grading}_nu{nu}"
    settings = ["Run/Write fields=false", "Mesh/Layout=o-grid",
                "Mesh/O-grid/Outer boundary=circle",
                f"Mesh/O-grid/Cells around={n}",
                f"Mesh/O-grid/Edge cell size={edge}",
                f"Mesh/O-grid/Radial grading={grading}",
                "Mesh/Region of interest/Local refinements=0",
                "Elasticity/Sides=fixed",
                f"Elasticity/Degree={degree}",
                f"Elasticity/Formulation={formulation}",
                "Elasticity/Linear solver/Preconditioner=cholesky"]
    settings += [f"Layer stack/{layer}/Poisson's ratio={nu}"
                 for layer in LAYERS]
    # wall time and peak resident memory of the ssc process (os.wait4)
    done = ssc_runner.run(PRM, settings, folder, name)
    if not done.ok:
        print(f"{name} failed: {done.stderr[:300]}")
        return None
    s = done.summary()
    K = s["stiffness_N_per_mm"]
    return dict(code="ssc", discretisation=f"Q{degree} {formulation}",
                nu=nu, mesh=f"n={n} h={edge} q={grading}", dofs=s["dofs"],
                K_N_per_mm=K, relative_error=K / reference - 1,
                wall_s=done.wall_s, memory_MB=done.max_rss_MB)


def run_calculix(nu, mesh, folder, reference):
    n, edge, grading, max_height = mesh
    r = cp.peer_3d(nu, n, edge, grading, folder, max_height=max_height,
                   reference=reference)
    return dict(code="CalculiX", discretisation="C3D20R", nu=nu,
                mesh=f"n={n} h={edge} q={grading} hmax={max_height}",
                dofs=r["equations"], K_N_per_mm=r["K"],
                relative_error=r["relative_error"], wall_s=r["time_s"],
                memory_MB=r["memory_MB"])


def fastest(rows, code, target):
    within = [r for r in rows if r["code"] == code and
              abs(float(r["relative_error"])) <= target]
    return min(within, key=lambda r: float(r["wall_s"])) if within else None


def plot(rows, nus):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(nus), figsize=(5.5 * len(nus), 5),
                             squeeze=False)
    for ax, nu in zip(axes[0], nus):
        for (code, disc), style in ((("CalculiX", "C3D20R"), "k-s"),
                                    (("ssc", "Q2 mixed"), "C0o"),
                                    (("ssc", "Q1 enhanced"), "C1^")):
            pts = sorted((float(r["wall_s"]),
                          abs(float(r["relative_error"])))
                         for r in rows if r["code"] == code and
                         r["discretisation"] == disc and
                         abs(float(r["nu"]) - nu) < 1e-12)
            if pts:
                ax.plot(*zip(*pts), style, label=f"{code} {disc}")
        for target in (0.01, 0.003):
            ax.axhline(target, color="grey", lw=0.6, ls=":")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time of the run, one core (s)")
        ax.set_ylabel("|K / K_ref - 1|")
        ax.set_title(f"layered bonded punch, nu = {nu}\n"
                     "reference: CalculiX CAX8R, converged", fontsize=9)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "peer_calculix.png"), dpi=110)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--nu", type=float, nargs="+",
                        default=[0.3, 0.49, 0.4999])
    parser.add_argument("--plot-only", action="store_true")
    args = parser.parse_args()
    path = os.path.join(OUT, "peer_calculix.csv")
    if args.plot_only:
        with open(path) as f:
            plot([dict(r, nu=float(r["nu"])) for r in csv.DictReader(f)],
                 args.nu)
        return
    folder = tempfile.mkdtemp(prefix="peer_calculix_")
    rows, references = [], {}
    for nu in args.nu:
        reference = cp.reference_stiffness(nu, folder)
        K_ref = references[nu] = reference["K"]
        print(f"nu = {nu}: reference (CalculiX CAX8R, axisymmetric) K = "
              f"{K_ref:.7g} N/mm +- {reference['relative_error_estimate']:.1e} "
              "relative", flush=True)
        peers = list(cp.PEER_MESHES)
        for i in range(max(len(SSC_MESHES), len(peers))):
            new_rows = []
            if i < len(peers):
                new_rows.append(run_calculix(nu, peers[i], folder, K_ref))
            if i < len(SSC_MESHES):
                new_rows.append(run_ssc(nu, *SSC_MESHES[i], folder, K_ref))
            for row in filter(None, new_rows):
                rows.append(row)
                print(" ".join(f"{k}={row[k]:.4g}"
                               if isinstance(row[k], float)
                               else f"{k}={row[k]}" for k in FIELDS),
                      flush=True)
    os.makedirs(OUT, exist_ok=True)
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    for nu in args.nu:
        same_nu = [r for r in rows if r["nu"] == nu]
        for target in (0.01, 0.003):
            for code in ("CalculiX", "ssc"):
                best = fastest(same_nu, code, target)
                print(f"nu = {nu}, within {target:.1%}: {code}: " + (
                    "none" if best is None else
                    f"{best['discretisation']} {best['mesh']}, "
                    f"{best['dofs']} DoFs, {float(best['wall_s']):.2f} s, "
                    f"{float(best['memory_MB']):.0f} MB, error "
                    f"{float(best['relative_error']):+.3%}"))
    plot(rows, args.nu)

if __name__ == "__main__":
    main()
