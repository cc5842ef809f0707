#!/usr/bin/python3
"""The independent check of ssc's finite-strain indentation: the forearm's
layers-only stack (no lobules, septa or ligaments), which is axisymmetric,
computed by CalculiX (ccx 2.20, axisymmetric CAX8R, NLGEOM) and by ssc in
3D on its o-grid, with the same energy, the same boundary conditions and
the same punch; forces compared at equal depths.

The problem (mm, N, MPa; z up, skin surface z = 0): a cylinder of radius
40 mm (the main scene's patch is 80 x 80 mm), the forearm layers with the
in vivo moduli of prm/regions/forearm_in_vivo.prm: skin 1.2 mm (E = 0.02),
SAT 2.5 (0.0307), SM 0.4 (0.06), DAT 2 (0.0307), deep 15 (0.0106), nu =
0.49 everywhere. Bottom and side fixed. A rigid flat punch of radius a =
2.5 mm, bonded (every top node with r <= a gets u_r = 0 and u_z = -d),
displacement-controlled; the force is the axial reaction on those nodes.

Energy, both codes: compressible neo-Hookean with the isochoric split and
the quadratic volumetric term,
    W = mu/2 (I1bar - 3) + kappa/2 (J - 1)^2,
mu = E / (2 (1 + nu)), kappa = E / (3 (1 - 2 nu)): ccx's *HYPERELASTIC,
NEO HOOKE with C10 = mu/2, D1 = 2/kappa; ssc's neo-Hookean with
`Volumetric energy = quadratic` (its default, the logarithmic kappa/4 (J^2
- 1 - 2 ln J), is not what ccx offers; at nu = 0.49 the fat is driven far
from J = 1 and the two forms differ in the answer).

The punch edge is sharp and bonded here (no edge contact, which ccx
cannot model as ssc does): the skin beside the punch passes through the
punch's wall in both codes alike. The check is of the finite-strain
solution of one mathematical problem, not of the scene's contact model.

Discretisations:
- ccx: CAX8R (reduced integration; ccx has no hybrid element) on the (r,
  z) grid of calculix_punch.axisymmetric_mesh, graded towards the punch
  edge from both sides and in depth, nodes on every interface and at r =
  a; at finite strain the smallest cells are 0.2 to 0.025 mm (CCX_MESHES;
  the 1e-5 mm of the linear reference inverts at once). Levels halve the
  grading and the largest size. *STATIC with automatic increments; forces
  at the requested depths through *TIME POINTS. ccx stops where its increments fall
  below the minimum (the singular edge folds): the depths reached are
  reported.
- ssc: Mesh/Layout = o-grid with a circular outer boundary, Q2, mixed
  (Q2-P1, the projected dilatation), the Cholesky preconditioner, one
  load step per requested depth (SSC_MESHES).

Run (about 25 minutes on one core; runs are kept in the work directory
and not repeated; prints a table, writes
results/axisymmetric_finite_strain.csv beside this script):

    /usr/bin/python3 \
        benchmarks/finite_strain_vs_calculix/axisymmetric_finite_strain.py
        [--depths 0.25 0.5 ...] [--contacts bonded frictionless]
        [--workdir DIR]

--quick is the test suite's version (app/axisymmetric_check): one mesh of
each code, 0.25 and 0.5 mm, exit status 1 if they differ by over 1 %.
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
import calculix_punch as cp  # noqa: E402
import ssc_runner  # noqa: E402

# (name, thickness mm, Young's modulus MPa), from the skin surface down:
# prm/regions/forearm.prm with the moduli of forearm_in_vivo.prm
LAYERS = [("SKIN", 1.2, 0.02), ("SAT", 2.5, 0.0307), ("SM", 0.4, 0.06),
          ("DAT", 2.0, 0.0307), ("DEEP", 15.0, 0.0106)]
NU = 0.49
RADIUS = 40.0
PUNCH = 2.5
ON_PUNCH = PUNCH * (1 + 1e-10)
GROWTH = cp.AXI_GROWTH      # 0.4, as the linear reference's grids
MAX_SIZE = cp.AXI_MAX_SIZE  # 2 mm


def moduli(E, nu=NU):
    """(mu, kappa) of Young's modulus E and Poisson's ratio nu."""
    return E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))


def ccx_mesh(level, edge_size):
    """Corner coordinates (r, z ascending) of the level's (r, z) grid with
    cells of edge_size at the punch edge."""
    return cp.axisymmetric_mesh(level, edge_size, GROWTH, MAX_SIZE,
                                layers=LAYERS, radius=RADIUS)


def ccx_input(r, z, depths, element="CAX8R", bonded=True):
    """The ccx input: the punch pressed to max(depths) in one *STATIC step
    with automatic increments, the total axial reaction on the punch nodes
    printed at each of depths (time = depth / max depth)."""
    L, sets, _ = cp.layered_axisymmetric_grid(
        r, z, LAYERS, element,
        f"forearm layers, {'bonded' if bonded else 'frictionless'} punch, "
        f"{element}, NLGEOM", ON_PUNCH)
    for name, nodes in sets.items():
        L.append(f"*NSET, NSET={name}")
        L += cp._lines(nodes)
    for name, _, E in LAYERS:
        mu, kappa = moduli(E)
        L += [f"*MATERIAL, NAME=M{name}", "*HYPERELASTIC, NEO HOOKE",
              f"{mu / 2!r}, {2 / kappa!r}",
              f"*SOLID SECTION, ELSET={name}, MATERIAL=M{name}"]
    d_max = max(depths)
    L += ["*TIME POINTS, NAME=DEPTHS"]
    L += cp._lines(f"{d / d_max!r}" for d in depths)
    L += ["*STEP, NLGEOM, INC=100000", "*STATIC",
          f"{0.25 / d_max!r}, 1.0, 1e-7, {0.5 / d_max!r}", "*BOUNDARY",
          "BOTTOM, 1, 2, 0.0", "SIDE, 1, 2, 0.0", "AXIS, 1, 1, 0.0"]
    if bonded:
        L.append("PUNCH, 1, 1, 0.0")
    L += [f"PUNCH, 2, 2, {-d_max!r}",
          "*NODE PRINT, NSET=PUNCH, TOTALS=ONLY, TIME POINTS=DEPTHS", "RF",
          "*END STEP"]
    return "\n".join(L) + "\n", (len(r) - 1) * (len(z) - 1)


def kept_ccx_run(workdir, job, text):
    """Runs ccx on text as job unless an earlier run of the same input is
    kept in workdir; a run that stops without converging keeps what it
    printed. Returns (the .dat file's text, dict(equations, time_s), None
    and nan for a kept run)."""
    inp, dat_file = (os.path.join(workdir, job + ext)
                     for ext in (".inp", ".dat"))
    out = dict(equations=None, time_s=float("nan"))
    if not (os.path.exists(dat_file) and os.path.exists(inp) and
            open(inp).read() == text):
        try:
            out = cp.run_ccx(workdir, job, text)
        except RuntimeError:  # no convergence: keep what was printed
            pass
    with open(dat_file) as f:
        return f.read(), out


def ccx_forces(level, edge_size, depths, workdir, element="CAX8R",
               bonded=True):
    """Punch force (N) at each of depths that ccx reaches on the level's
    mesh: dict(depths, forces, equations, time_s, stopped (ccx ended before
    the last depth), level, cells)."""
    r, z = ccx_mesh(level, edge_size)
    text, cells = ccx_input(r, z, depths, element, bonded)
    job = (f"forearm_layers_{'bonded' if bonded else 'frictionless'}_"
           f"{element}_l{level}_h{edge_size}")
    dat, out = kept_ccx_run(workdir, job, text)
    times = [float(t) for t in re.findall(
        r"total force \(fx,fy,fz\) for set \S+ and time\s+(\S+)", dat)]
    fy = [f[1] for f in cp.total_forces(dat)]
    d_max = max(depths)
    return dict(depths=[round(t * d_max, 6) for t in times],
                forces=[-180 * f for f in fy], equations=out["equations"],
                time_s=out["time_s"], stopped=len(times) < len(depths),
                level=level, cells=cells)


# --------------------------------------------------------------------------
# ssc on the o-grid
# --------------------------------------------------------------------------
SSC = ssc_runner.SSC
PRM = os.path.join(HERE, "forearm_layers_axisymmetric.prm")
# o-grid (cells around, edge cell size mm, radial grading), coarse to fine
SSC_MESHES = [(8, 0.4, 1.8), (8, 0.2, 1.6), (8, 0.1, 1.4)]
# ccx (level, edge size mm), coarse to fine
SSC_TIMEOUT = 1200  # s: beyond the depths a mesh can reach Newton crawls
# (level 3 with 0.0125 mm: 0.4 mm deep after 7 minutes, too slow)
CCX_MESHES = [(0, 0.2), (1, 0.1), (1, 0.05), (2, 0.025)]


def ssc_forces(mesh, depths, workdir, bonded=True, ssc=SSC, overrides=(),
               prefix="ogrid"):
    """Punch force (N) at each of depths (equal steps from 0) that ssc
    reaches on the o-grid mesh (n, h, q), one process (the Cholesky
    preconditioner), with the further parameter overrides ("Section/Name=
    value"), in the run folder named from prefix: dict(depths, forces,
    dofs, time_s, stopped)."""
    n, h, q = mesh
    step = depths[0]
    assert all(abs(d - step * (k + 1)) < 1e-12 for k, d in enumerate(depths))
    name = (f"{prefix}_{'bonded' if bonded else 'frictionless'}_n{n}_h{h}"
            f"_q{q}_d{depths[-1]}_s{len(depths)}")
    settings = ["Run/Write fields=false",
                f"Mesh/O-grid/Cells around={n}",
                f"Mesh/O-grid/Edge cell size={h}",
                f"Mesh/O-grid/Radial grading={q}",
                f"Punch/Depth={depths[-1]}",
                f"Punch/Load steps={len(depths)}",
                f"Punch/Contact={'bonded' if bonded else 'frictionless'}"]
    folder = os.path.join(workdir, name)
    table = os.path.join(folder, "force_displacement.csv")
    failed, wall = False, math.nan
    if not os.path.exists(table):  # else kept from an earlier run
        start = time.perf_counter()
        try:
            failed = not ssc_runner.run(PRM, settings + list(overrides),
                                        workdir, name, ssc=ssc,
                                        timeout=SSC_TIMEOUT).ok
        except subprocess.TimeoutExpired:
            failed = True
        wall = time.perf_counter() - start
    reached, forces = [], []
    if os.path.exists(table):
        for row in ssc_runner.read_table(folder):
            reached.append(float(row["depth_mm"]))
            forces.append(float(row["force_N"]))
    dofs = ssc_runner.read_summary(folder)["dofs"] \
        if os.path.exists(os.path.join(folder, "summary.json")) else None
    return dict(depths=reached, forces=forces, time_s=wall, dofs=dofs,
                stopped=failed)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--workdir", default="/tmp/axisymmetric_check")
    parser.add_argument("--depths", type=float, nargs="+",
                        default=[0.25, 0.5, 0.75, 1.0, 1.25, 1.5])
    parser.add_argument("--csv", default=os.path.join(
        HERE, "results", "axisymmetric_finite_strain.csv"))
    parser.add_argument("--quick", action="store_true",
                        help="the test suite's small version: one mesh of "
                        "each code, bonded, 0.25 and 0.5 mm; exit status 1 "
                        "if they differ by more than 1 %%")
    parser.add_argument("--ssc", default=SSC, help="the ssc executable")
    parser.add_argument("--contacts", nargs="+", default=["bonded"],
                        choices=["bonded", "frictionless"])
    args = parser.parse_args()
    if args.quick:
        return quick(args.ssc, args.workdir)
    rows = []
    for contact in args.contacts:
        bonded = contact == "bonded"
        runs = []
        for level, h in CCX_MESHES:
            r = ccx_forces(level, h, args.depths, args.workdir,
                           bonded=bonded)
            runs.append(("ccx", f"CAX8R level {level} h {h}",
                         r["cells"], r))
        for mesh in SSC_MESHES:
            r = ssc_forces(mesh, args.depths, args.workdir, bonded)
            runs.append(("ssc", "Q2-P1 o-grid n {} h {} q {}".format(*mesh),
                         r["dofs"], r))
        for code, mesh, size, r in runs:
            print(f"{contact:12s} {code} {mesh:32s} {size}: reached "
                  f"{max(r['depths'], default=0)} mm", flush=True)
            for d, f in zip(r["depths"], r["forces"]):
                rows.append(dict(contact=contact, code=code, mesh=mesh,
                                 size=size, depth_mm=d, force_N=f))
    write_rows(args.csv, rows)
    print("\ncontact       depth  ccx finest (change from previous)  "
          "ssc finest (change)  ssc - ccx")
    for contact in args.contacts:
        print_finest([r for r in rows if r["contact"] == contact],
                     args.depths, f"{contact:12s} ")


def write_rows(path, rows):
    """Writes the result rows (dicts with the same keys) as CSV."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def print_finest(rows, depths, prefix=""):
    """At every depth, the force of the finest mesh of each code (the last
    row of that code there) with its change from the one before, and ssc's
    difference from ccx."""
    for d in depths:
        best = {}
        for code in ("ccx", "ssc"):
            at = [r["force_N"] for r in rows
                  if r["code"] == code and abs(r["depth_mm"] - d) < 1e-9]
            if at:
                change = (at[-1] / at[-2] - 1) if len(at) > 1 else math.nan
                best[code] = (at[-1], change)
        if len(best) == 2:
            (fc, cc), (fs, cs) = best["ccx"], best["ssc"]
            print(f"{prefix}{d:5.2f}  {fc:.6f} ({cc:+.2%})  "
                  f"{fs:.6f} ({cs:+.2%})  {fs / fc - 1:+.2%}")


def quick(ssc, workdir, depths=(0.25, 0.5), tolerance=0.01):
    """The small version: ccx on level 1 with 0.05 mm at the edge (0.15 %
    above level 2 with 0.025 mm at 0.25 and 0.5 mm), ssc on the o-grid
    with 8 cells around and 0.2 mm at the edge (0.06 % and 0.03 % above
    0.1 mm); they are 0.40 % apart (2026-12-04). Returns the exit
    status."""
    shutil.rmtree(workdir, ignore_errors=True)  # nothing kept: run both
    c = ccx_forces(1, 0.05, list(depths), workdir)
    s = ssc_forces((8, 0.2, 1.6), list(depths), workdir, True, ssc)
    return compare_quick(c, s, depths, tolerance)


def compare_quick(c, s, depths, tolerance):
    """Prints ccx's (c) and ssc's (s) forces at each depth and whether they
    agree within tolerance; returns the exit status (1 if not, or if a
    depth was not reached)."""
    status = 0
    for d in depths:
        fc = dict(zip(c["depths"], c["forces"])).get(d)
        fs = dict(zip(s["depths"], s["forces"])).get(d)
        if fc is None or fs is None:
            print(f"depth {d} mm: not reached (ccx {fc}, ssc {fs})")
            status = 1
            continue
        ok = abs(fs / fc - 1) <= tolerance
        status = status if ok else 1
        print(f"depth {d} mm: CalculiX CAX8R {fc:.5f} N, ssc Q2-P1 "
              f"{fs:.5f} N, within {tolerance:.0%}: {'yes' if ok else 'NO'} "
              f"({fs / fc - 1:+.2%})")
    return status


if __name__ == "__main__":
    sys.exit(main())
