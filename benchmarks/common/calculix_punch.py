#!/usr/bin/python3
"""CalculiX (ccx 2.20, Debian's calculix-ccx) on the layered, bonded flat
punch: (A) a converged axisymmetric reference stiffness, (B) a 3D peer run
(20-node hexahedra on an O-grid) whose time and memory can be set against
ours at equal error.

The problem (mm, N, MPa; z up, skin surface z = 0; linear elasticity): a
cylinder of radius R = 30 mm, layers from the top skin 1.5 mm (E = 0.02),
SAT 3 mm (0.001), SM 0.5 mm (0.06), DAT 3 mm (0.001), deep 10 mm (0.015),
one Poisson ratio nu for all. Bottom z = -18 and side r = R fixed; every
top node with r <= a (1 + 1e-10), a = 2.5 mm, gets u_r = 0 (3D: u_x = u_y
= 0) and u_z = -d, d = 0.5 mm. K = (vertical reaction on the punch nodes)
/ d, N/mm.

What this relies on in CalculiX, and how it was checked (2026-12-03):

* Elements. ccx 2.20 has CAX8 and CAX8R for axisymmetry and no hybrid or
  mixed element at all (no CAX8H, no C3D20H). ccx expands every 2D element
  into a 3D wedge of 20-node bricks spanning +-1 degree about the axis
  (CAX8 -> C3D20, 27 Gauss points; CAX8R -> C3D20R, 8), tied to the 2D
  nodes by MPCs; the number of equations stays that of the 2D mesh. x is
  r, y is z (the axis). CAX8R is the reference element. At nu = 0.3 CAX8
  and CAX8R reach the same value (the CAX8 extrapolation is 1e-7 from the
  CAX8R result); at nu = 0.49 CAX8 converges from above at a lower rate
  (its extrapolation is 6e-6 above CAX8R's finest, inside the two
  sequences' uncertainties); at nu = 0.4999 CAX8 locks (+4.4 % at 16k
  equations, +0.21 % at 208k). CAX8R's differences shrink by a factor 6-20
  per level at nu = 0.3 and 0.4999; at nu = 0.49 its sequence is not
  monotone (reduced integration gives no bound) but moves by less than
  3e-6 after the second level.
* Axisymmetric reactions refer to a 2 degree segment: the ring force is
  180 * RF. check_axisymmetric_force_convention() verifies this on
  closed-form cases for CAX8 and CAX8R and raises otherwise: a disc in
  lubricated uniaxial compression (F = E eps pi R^2), and a quadratic
  displacement field solving Navier's equations (so the Q8 solution is
  exact) prescribed on the whole boundary, at nu = 0.3 and 0.4999, with
  shear on the side face and nodes on the axis, where the axial totals of
  the top and the side nodes have closed forms. All agree to the 7
  printed digits (1e-9 to 1.2e-7). Only the axial (y) component is used:
  the radial (x) reaction components of axisymmetric nodes are not the
  consistent ring forces in ccx 2.20 (a thick-walled cylinder with
  prescribed inner displacement: their total is off by an amount that
  scales with the size of the element at the boundary, -1.2 % with 20
  elements, -0.08 % with 320; the corner nodes report 0). Displacements
  printed for axisymmetric nodes are low by theta^2 / 6 = 5.1e-5 (theta
  = 1 degree; an average over the expanded nodes); forces are unaffected.
* Reaction output: *NODE PRINT, NSET=PUNCH, TOTALS=ONLY with RF writes the
  summed reaction to the .dat file with 7 significant digits (relative
  resolution 5e-8 to 5e-7, included in the reference's error estimate).
* Reference mesh: a structured (r, z) tensor grid graded towards the punch
  edge (r = a, z = 0), from both sides radially and in depth, with nodes
  on every layer interface and at r = a. Element sizes follow h(s) =
  min(h_max, h_e + g s), s the radial distance from r = a or the depth:
  a geometric grading of ratio about 1 + g, capped at h_max. A level n
  halves g and h_max, from g = 0.4, h_max = 2 mm (16k equations) to level
  3 (740k equations, about 55 s and 5.3 GB); h_e = 1e-5 mm is fixed. The
  singular element's error is about 0.06 h_e / mm relative (6e-7 here),
  measured from a run with 4 h_e. Smaller h_e do not help: at nu = 0.4999
  K then jumps by +1e-5 (round-off: tensor-product cells with aspect
  ratios h_max / h_e beyond 1e5, bulk to shear modulus 5000).
* Solver: this ccx is linked against SPOOLES only (no PARDISO, no PaStiX),
  so *STATIC uses SPOOLES' symmetric direct solver (the log says "Factoring
  the system of equations using the symmetric spooles solver"; parsed and
  returned as 'solver'). Runs use OMP_NUM_THREADS = 1 and CCX_NPROC_* = 1
  ("Using up to 1 cpu(s) for spooles").
* Time and memory: wall time of the ccx process (perf_counter around it),
  CPU time and peak resident memory from /usr/bin/time -v (or
  getrusage(RUSAGE_CHILDREN), the largest child so far, if it is
  missing). They cover ccx reading the input, assembly, factorisation and
  writing the .dat file, not Python writing the input. Runs are niced
  (nice -n 5).
* 3D peer: C3D20R (C3D20 for comparison) on an O-grid, the construction of
  ssc's Mesh/Layout = o-grid (source/mesh/o_grid.cc) with a circular outer
  boundary: a square core of (n/4)^2 quadrilaterals, blend rings from the
  core's square to the first circle, circular rings graded radially
  towards r = a from both sides (size h_e at the circle, ratio q, capped
  at the spacing around 2 pi r / n) out to r = R, angles uniform from -45
  degrees. Midside nodes of edges along a circle lie on the circle, all
  others at edge midpoints. The quadratic arcs still cut the circle's
  area by 7.8e-4 (n = 8), 1.5e-4 (12), 5e-5 (16) relative: the n = 8
  meshes are about 0.015 % softer than n = 12 or 16 with the same h_e, q
  (measured at nu = 0.49), which offsets part of their discretisation
  error. In z, layer-conforming slices: heights start at h_e at the
  surface and grow by q (at most max_height), continued from layer to
  layer; per layer a last height overshooting by more than half of it is
  dropped, the heights are scaled to the thickness, and a layer has at
  least two slices (as ssc's "Grade in depth"; with one C3D20R through
  the 3 mm DAT layer K was +2.7 % off instead of +0.46 % at nu = 0.4999
  and 45k equations).
* 3D findings (one thread): at nu = 0.3 and 0.49 C3D20R converges cleanly
  (0.49: +1.6 % at 14k equations, +0.12 % at 45k, +0.017 % at 155k);
  C3D20 locks mildly at 0.49 (+1.1 % at 45k, +0.98 % at 68k) and badly at
  0.4999 (+7.4 % at 68k). At nu = 0.4999 C3D20R converges more slowly
  (+0.46 % at 45k, +0.13 % at 155k), mostly governed by the grading
  ratio; no hourglass pattern in the surface displacement. Eight cells
  around suffice (the field is axisymmetric); h_e and q decide the
  error. SPOOLES needs about 14 kB per equation at 155k equations.

Usable from another script:

    import calculix_punch as cp
    cp.check_axisymmetric_force_convention("/tmp/ccx")
    cp.axisymmetric_stiffness(0.49, 2, "/tmp/ccx")    # one level
    cp.reference_stiffness(0.49, "/tmp/ccx")          # about 90 s, 5.3 GB
    cp.peer_3d(0.49, 8, 0.02, 1.5, "/tmp/ccx", max_height=2.5,
               reference=0.03524278)

Run (prints tables; files go to the work directory only):

    /usr/bin/python3 benchmarks/common/calculix_punch.py [--nu 0.3 0.49 0.4999]
        [--quick] [--skip-3d] [--full-integration] [--workdir DIR]
        [--csv FILE]

The full run (three nu, references and six 3D meshes each) takes about
12 minutes on one core.
"""
import argparse
import csv
import math
import os
import re
import resource
import shutil
import subprocess
import tempfile
import time

import numpy as np

CCX = shutil.which("ccx") or "/usr/bin/ccx"
TIME = "/usr/bin/time" if os.path.exists("/usr/bin/time") else None

# (name, thickness mm, Young's modulus MPa), from the skin surface down
LAYERS = [("SKIN", 1.5, 0.02), ("SAT", 3.0, 0.001), ("SM", 0.5, 0.06),
          ("DAT", 3.0, 0.001), ("DEEP", 10.0, 0.015)]
RADIUS = 30.0    # outer radius, mm
PUNCH = 2.5      # punch radius a, mm
INDENT = 0.5     # punch displacement d, mm
DEPTH = sum(t for _, t, _ in LAYERS)
ON_PUNCH = PUNCH * (1 + 1e-10)

# axisymmetric reference mesh: h(s) = min(h_max, h_e + g s) at level 0, a
# level halving g and h_max
AXI_EDGE_SIZE = 1e-5
AXI_GROWTH = 0.4
AXI_MAX_SIZE = 2.0
REFERENCE_LEVELS = (0, 1, 2, 3)

# 3D peer meshes (cells around n, edge size h_e mm, ratio q, max height
# mm): 7k to 155k equations, 1 to 75 s; eight cells around suffice (the
# field is axisymmetric), the grading ratio q and h_e decide the error
PEER_MESHES = [(8, 0.6, 2.5, 5.0), (8, 0.2, 1.8, 3.0), (8, 0.1, 1.6, 3.0),
               (8, 0.02, 1.5, 2.5), (8, 0.005, 1.5, 2.0),
               (8, 0.005, 1.3, 1.0)]


# --------------------------------------------------------------------------
# running ccx
# --------------------------------------------------------------------------
def _lines(values, per_line=16):
    """ccx reads at most 16 entries per data line."""
    values = list(values)
    return [", ".join(str(v) for v in values[k:k + per_line])
            for k in range(0, len(values), per_line)]


def _fmt(x):
    """A coordinate for ccx: at most 20 characters per field."""
    return f"{x:.12e}"


def run_ccx(workdir, job, text, threads=1, niceness=5, timeout=None):
    """Writes job.inp into workdir, runs ccx on it (niced, with threads
    threads, stopped after timeout seconds if given) and returns dict(dat
    (the .dat file), log (ccx's output), equations, solver, time_s (wall),
    cpu_s, memory_MB (peak resident)); the .frd results, unused and large,
    are deleted. Raises RuntimeError if ccx reports an error or writes no
    .dat file."""
    os.makedirs(workdir, exist_ok=True)
    with open(os.path.join(workdir, job + ".inp"), "w") as f:
        f.write(text)
    for ext in (".dat", ".frd", ".sta", ".cvg"):
        if os.path.exists(os.path.join(workdir, job + ext)):
            os.remove(os.path.join(workdir, job + ext))
    n = str(threads)
    env = dict(os.environ, OMP_NUM_THREADS=n, CCX_NPROC_EQUATION_SOLVER=n,
               CCX_NPROC_STIFFNESS=n, CCX_NPROC_RESULTS=n)
    args = ["nice", "-n", str(niceness), CCX, "-i", job]
    if TIME:
        args = [TIME, "-v"] + args
    start = time.perf_counter()
    p = subprocess.run(args, cwd=workdir, env=env, capture_output=True,
                       text=True, timeout=timeout)
    wall = time.perf_counter() - start
    if TIME:
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)",
                      p.stderr)
        memory = int(m.group(1)) / 1024 if m else float("nan")
        cpu = sum(float(v) for v in re.findall(
            r"(?:User|System) time \(seconds\): ([\d.]+)", p.stderr))
    else:  # the largest child so far, in kB on Linux
        usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        memory = usage.ru_maxrss / 1024
        cpu = float("nan")
    log = p.stdout
    dat_path = os.path.join(workdir, job + ".dat")
    if p.returncode != 0 or "*ERROR" in log or not os.path.exists(dat_path):
        errors = [l for l in log.splitlines() if "ERROR" in l]
        raise RuntimeError(f"ccx failed on {workdir}/{job}.inp "
                           f"(exit {p.returncode}): {errors[:5]}\n"
                           f"{log[-2000:]}{p.stderr[-1000:]}")
    with open(dat_path) as f:
        dat = f.read()
    frd_path = os.path.join(workdir, job + ".frd")
    if os.path.exists(frd_path):
        os.remove(frd_path)
    m = re.search(r"number of equations\s+(\d+)", log)
    solver = re.search(r"Factoring the system of equations using the (.*)",
                       log)
    return dict(dat=dat, log=log, equations=int(m.group(1)) if m else None,
                solver=solver.group(1).strip() if solver else "unknown",
                time_s=wall, cpu_s=cpu, memory_MB=memory)


def print_resolution(value):
    """Half a unit of the last of the 7 significant digits ccx prints."""
    if value == 0:
        return 0.0
    return 0.5 * 10.0 ** (math.floor(math.log10(abs(value))) - 6)


def total_forces(dat):
    """The (fx, fy, fz) of every 'total force' block of a .dat file, in the
    order of the *NODE PRINT requests."""
    return [tuple(float(v) for v in m.groups()) for m in re.finditer(
        r"total force \(fx,fy,fz\) for set \S+ and time\s+\S+\s*\n\s*\n"
        r"\s*(\S+)\s+(\S+)\s+(\S+)", dat)]


def richardson(values):
    """Richardson extrapolation of the last three of a sequence of
    refinements: (limit, ratio of the last two differences). Where the
    differences do not shrink monotonically (ratio not in (0, 1)) the limit
    is nan."""
    k1, k2, k3 = values[-3:]
    if k2 == k1:
        return float("nan"), float("nan")
    ratio = (k3 - k2) / (k2 - k1)
    if not 0 < ratio < 1:
        return float("nan"), ratio
    return k3 + (k3 - k2) * ratio / (1 - ratio), ratio


# --------------------------------------------------------------------------
# the force convention of axisymmetric elements
# --------------------------------------------------------------------------
def _brick20(e, nodes):
    """The data lines of 20-node element e: ccx takes at most 16 entries
    per line, so the line continues on a second one."""
    return [f"{e}, " + ", ".join(map(str, nodes[:15])) + ",",
            ", ".join(map(str, nodes[15:]))]


def _element_sets(elsets):
    """The *ELSET blocks of elsets ({name: elements})."""
    L = []
    for name, elements in elsets.items():
        L.append(f"*ELSET, ELSET={name}")
        L += _lines(elements)
    return L


def _node_sets_and_layers(sets, nu):
    """The *NSET blocks of sets ({name: nodes}) and each layer's material
    (E, nu) and solid section on its element set."""
    L = []
    for name, nodes in sets.items():
        L.append(f"*NSET, NSET={name}")
        L += _lines(nodes)
    for name, _, E in LAYERS:
        L += [f"*MATERIAL, NAME=M{name}", "*ELASTIC", f"{E!r}, {nu!r}",
              f"*SOLID SECTION, ELSET={name}, MATERIAL=M{name}"]
    return L


def _quad8(nid, i, j):
    """The 8 node ids of the quadratic quadrilateral whose lower-left corner
    is node (i, j) of a grid with midside nodes (corners first,
    counter-clockwise, then the midsides), as ccx's CAX8 wants them."""
    return ", ".join(str(n) for n in (
        nid(i, j), nid(i + 2, j), nid(i + 2, j + 2), nid(i, j + 2),
        nid(i + 1, j), nid(i + 2, j + 1), nid(i + 1, j + 2), nid(i, j + 1)))


def _axisymmetric_grid_input(r, z, element, material, boundary, prints):
    """An (r, z) tensor grid of 8-node quadrilaterals (corner coordinates r,
    z ascending; midside nodes at the midpoints), one material. boundary:
    function (i, j, R, Z) of the node's full-grid indices and coordinates ->
    list of (dof, value); prints: dict set name -> predicate (i, j)."""
    R = np.empty(2 * len(r) - 1)
    R[0::2], R[1::2] = r, 0.5 * (r[1:] + r[:-1])
    Z = np.empty(2 * len(z) - 1)
    Z[0::2], Z[1::2] = z, 0.5 * (z[1:] + z[:-1])
    nid = lambda i, j: j * len(R) + i + 1
    nodes = [(i, j) for j in range(len(Z)) for i in range(len(R))
             if not (i % 2 and j % 2)]
    L = ["*HEADING", "axisymmetric check", "*NODE"]
    L += [f"{nid(i, j)}, {_fmt(R[i])}, {_fmt(Z[j])}" for i, j in nodes]
    L.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    e = 0
    for jj in range(len(z) - 1):
        for ii in range(len(r) - 1):
            i, j = 2 * ii, 2 * jj
            e += 1
            L.append(f"{e}, " + _quad8(nid, i, j))
    for name, where in prints.items():
        L.append(f"*NSET, NSET={name}")
        L += _lines(nid(i, j) for i, j in nodes if where(i, j))
    E, nu = material
    L += ["*MATERIAL, NAME=M", "*ELASTIC", f"{E!r}, {nu!r}",
          "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "*STEP", "*STATIC",
          "*BOUNDARY"]
    for i, j in nodes:
        for dof, value in boundary(i, j, R[i], Z[j]):
            L.append(f"{nid(i, j)}, {dof}, {dof}, {_fmt(value)}")
    for name in prints:
        L += [f"*NODE PRINT, NSET={name}, TOTALS=ONLY", "RF"]
    L.append("*END STEP")
    return "\n".join(L) + "\n"


def check_axisymmetric_force_convention(workdir, tolerance=2e-6):
    """Verifies that ccx reports reaction forces of axisymmetric elements
    (CAX8, CAX8R) for a 2 degree segment, i.e. the ring force is 180 * RF
    (axial component), on two closed-form cases; raises AssertionError
    otherwise. Returns a list of (case, element, ccx * 180, exact).

    1. A disc (R = 2, height 1, E = 100, nu = 0.3) between lubricated
       plates, compressed by 1 %: u_z = 0 at the bottom, u_z = -0.01 at the
       top, u_r free: uniaxial stress, F = E eps pi R^2 on the top nodes.
    2. u_r = a1 r + a2 r z, u_z = b1 z + b2 r^2 + b3 z^2 with b2 from
       Navier's equations (no body force), prescribed on the whole boundary
       of r in [0, 2], z in [0, 1.5] (a graded 4 x 3 mesh, nu = 0.3 and
       0.4999): the Q8 solution is exact, so the reactions are the
       consistent nodal forces of the tractions. Axial totals: on the top
       nodes sigma_zz pi R^2 plus the top corner's share of the side shear,
       on the side nodes (without the corners) sigma_rz 2 pi R (H - h_top /
       6 - h_bottom / 6). So the factor is checked on nodes carrying
       shear and on nodes on the axis, too.
    """
    results = []
    for element in ("CAX8", "CAX8R"):
        # 1. uniaxial compression
        E, nu, Rc, H, eps = 100.0, 0.3, 2.0, 1.0, 0.01
        text = _axisymmetric_grid_input(
            np.array([0.0, Rc]), np.array([0.0, H]), element, (E, nu),
            lambda i, j, r, z: ([(2, 0.0)] if j == 0 else
                                [(2, -eps * H)] if j == 2 else []),
            {"TOP": lambda i, j: j == 2})
        out = run_ccx(workdir, "convention_uniaxial", text)
        fy = total_forces(out["dat"])[0][1]
        results.append(("uniaxial, top", element, -180 * fy,
                        E * eps * math.pi * Rc ** 2))
        # 2. an exact quadratic field with shear
        for nu in (0.3, 0.4999):
            lam = E * nu / (1 + nu) / (1 - 2 * nu)
            mu = E / 2 / (1 + nu)
            a1, a2, b1, b3 = 0.001, 0.002, -0.003, 0.0015
            b2 = -((lam + mu) * (2 * a2 + 2 * b3) + 2 * mu * b3) / (4 * mu)
            r = np.array([0.0, 0.3, 0.9, 1.2, 2.0])
            z = np.array([0.0, 0.2, 0.7, 1.5])
            Rc, H = r[-1], z[-1]
            last_i, last_j = 2 * len(r) - 2, 2 * len(z) - 2

            def boundary(i, j, rr, zz):
                if i in (0, last_i) or j in (0, last_j):
                    return [(1, a1 * rr + a2 * rr * zz),
                            (2, b1 * zz + b2 * rr ** 2 + b3 * zz ** 2)]
                return []

            text = _axisymmetric_grid_input(
                r, z, element, (E, nu), boundary,
                {"TOP": lambda i, j: j == last_j,
                 "SIDE": lambda i, j: i == last_i and 0 < j < last_j})
            out = run_ccx(workdir, "convention_quadratic", text)
            (_, top, _), (_, side, _) = total_forces(out["dat"])
            szz = lam * (2 * a1 + 2 * a2 * H + b1 + 2 * b3 * H) + \
                2 * mu * (b1 + 2 * b3 * H)
            srz = mu * (a2 + 2 * b2) * Rc
            h_top, h_bottom = z[-1] - z[-2], z[1] - z[0]
            results.append((f"quadratic field nu={nu}, top", element,
                            180 * top, szz * math.pi * Rc ** 2 +
                            srz * 2 * math.pi * Rc * h_top / 6))
            results.append((f"quadratic field nu={nu}, side", element,
                            180 * side, srz * 2 * math.pi * Rc *
                            (H - h_top / 6 - h_bottom / 6)))
    for case, element, ccx, exact in results:
        if abs(ccx / exact - 1) > tolerance:
            raise AssertionError(
                f"axisymmetric force convention: {case} ({element}): 180 * "
                f"RF = {ccx:.7g}, closed form {exact:.7g} (ratio "
                f"{ccx / exact:.6g}); ccx does not report forces for a "
                f"2 degree segment as assumed")
    return results


# --------------------------------------------------------------------------
# (A) axisymmetric reference
# --------------------------------------------------------------------------
def graded_segment(s0, s1, edge_size, growth, max_size):
    """Points from s0 to s1 (0 <= s0 < s1, distances from a singular point)
    whose spacing follows h(s) = min(max_size, edge_size + growth s): the
    number of intervals is the integral of 1 / h rounded up, the points
    equidistribute it."""
    sc = (max_size - edge_size) / growth if growth > 0 else math.inf

    def G(s):  # integral of 1 / h from 0 to s
        if growth == 0:
            return s / edge_size
        if s <= sc:
            return math.log1p(growth * s / edge_size) / growth
        return math.log1p(growth * sc / edge_size) / growth + \
            (s - sc) / max_size

    def G_inverse(g):
        gc = G(sc) if sc < math.inf else math.inf
        if g <= gc:
            return edge_size * math.expm1(growth * g) / growth \
                if growth > 0 else g * edge_size
        return sc + (g - gc) * max_size

    g0, g1 = G(s0), G(s1)
    n = max(1, math.ceil(g1 - g0 - 1e-9))
    points = [G_inverse(g0 + (g1 - g0) * k / n) for k in range(n + 1)]
    points[0], points[-1] = s0, s1
    return points


def axisymmetric_mesh(level, edge_size=AXI_EDGE_SIZE, growth=AXI_GROWTH,
                      max_size=AXI_MAX_SIZE, layers=LAYERS, radius=RADIUS):
    """Corner coordinates (r ascending, z ascending) of the reference grid
    at a level: sizes min(max_size, edge_size + growth s) / 2^level in
    growth and max_size, s the distance from r = a radially and from z = 0
    in depth; nodes at r = a and on every interface of layers (name,
    thickness, modulus), out to radius."""
    g, h = growth / 2 ** level, max_size / 2 ** level
    left = graded_segment(0.0, PUNCH, edge_size, g, h)
    right = graded_segment(0.0, radius - PUNCH, edge_size, g, h)
    r = sorted([PUNCH - s for s in left] + [PUNCH + s for s in right[1:]])
    r[0] = 0.0
    z, top = [0.0], 0.0
    for _, thickness, _ in layers:
        z += [-s for s in
              graded_segment(top, top + thickness, edge_size, g, h)[1:]]
        top += thickness
    z[-1] = -top
    return np.array(r), np.array(sorted(z))


def layered_axisymmetric_grid(r, z, layers, element, heading,
                              on_punch=ON_PUNCH):
    """The nodes, elements (8-node quadrilaterals of type element, midside
    nodes at the midpoints) and per-layer element sets of the (r, z) grid
    (corner coordinates ascending; x = r, y = z), layers (name, thickness,
    modulus) from the top z = 0 down, and the node sets BOTTOM, SIDE, AXIS
    and PUNCH (top nodes with r <= on_punch): (input lines, node sets,
    number of nodes)."""
    R = np.empty(2 * len(r) - 1)
    R[0::2], R[1::2] = r, 0.5 * (r[1:] + r[:-1])
    Z = np.empty(2 * len(z) - 1)
    Z[0::2], Z[1::2] = z, 0.5 * (z[1:] + z[:-1])
    NR, NZ = len(R), len(Z)
    nid = lambda i, j: j * NR + i + 1
    L = ["*HEADING", heading, "*NODE"]
    L += [f"{nid(i, j)}, {_fmt(R[i])}, {_fmt(Z[j])}"
          for j in range(NZ) for i in range(NR) if not (i % 2 and j % 2)]
    L.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    bottoms = -np.cumsum([t for _, t, _ in layers])  # layer bottoms
    elsets = {name: [] for name, _, _ in layers}
    e = 0
    for jj in range(len(z) - 1):
        layer = layers[int(np.searchsorted(-bottoms,
                                           -0.5 * (z[jj] + z[jj + 1])))][0]
        for ii in range(len(r) - 1):
            i, j = 2 * ii, 2 * jj
            e += 1
            L.append(f"{e}, " + _quad8(nid, i, j))
            elsets[layer].append(e)
    for name, elements in elsets.items():
        L.append(f"*ELSET, ELSET={name}")
        L += _lines(elements)
    sets = {"BOTTOM": [nid(i, 0) for i in range(NR)],
            "SIDE": [nid(NR - 1, j) for j in range(NZ)],
            "AXIS": [nid(0, j) for j in range(NZ)],
            "PUNCH": [nid(i, NZ - 1) for i in range(NR) if R[i] <= on_punch]}
    return L, sets, NR * NZ - (NR // 2) * (NZ // 2)


def axisymmetric_input(nu, r, z, element="CAX8R"):
    """The ccx input of the punch on the (r, z) grid (x = r, y = z)."""
    L, sets, n_nodes = layered_axisymmetric_grid(
        r, z, LAYERS, element, f"bonded punch, axisymmetric {element}, "
        f"nu = {nu}")
    L += _node_sets_and_layers(sets, nu)
    L += ["*STEP", "*STATIC", "*BOUNDARY", "BOTTOM, 1, 2, 0.0",
          "SIDE, 1, 2, 0.0", "AXIS, 1, 1, 0.0", "PUNCH, 1, 1, 0.0",
          f"PUNCH, 2, 2, {-INDENT!r}",
          "*NODE PRINT, NSET=PUNCH, TOTALS=ONLY", "RF", "*END STEP"]
    return "\n".join(L) + "\n", n_nodes, (len(r) - 1) * (len(z) - 1)


def axisymmetric_stiffness(nu, level, workdir, element="CAX8R",
                           edge_size=AXI_EDGE_SIZE, growth=AXI_GROWTH,
                           max_size=AXI_MAX_SIZE):
    """Stiffness K (N/mm) of the axisymmetric model at a refinement level
    (see axisymmetric_mesh); the ring force is 180 times ccx's total axial
    reaction on the punch nodes. Returns dict(K, n_nodes, n_elements,
    equations, time_s, cpu_s, memory_MB, resolution (of K from the printed
    digits), element, level, nu, solver)."""
    r, z = axisymmetric_mesh(level, edge_size, growth, max_size)
    text, n_nodes, n_elements = axisymmetric_input(nu, r, z, element)
    out = run_ccx(workdir, f"axi_{element}_nu{nu}_l{level}_h{edge_size}",
                  text)
    fy = total_forces(out["dat"])[0][1]
    return dict(K=-180 * fy / INDENT, n_nodes=n_nodes,
                n_elements=n_elements, equations=out["equations"],
                time_s=out["time_s"], cpu_s=out["cpu_s"],
                memory_MB=out["memory_MB"],
                resolution=180 * print_resolution(fy) / INDENT,
                element=element, level=level, nu=nu, solver=out["solver"])


def reference_stiffness(nu, workdir, levels=REFERENCE_LEVELS,
                        element="CAX8R", edge_check=True, verbose=False):
    """The converged axisymmetric stiffness: CAX8R on the levels given
    (default 0-3, 16k to 740k equations; about 90 s in all on one core,
    5.3 GB at the finest), each halving the grading g and h_max at a fixed
    edge size h_e.

    K is the finest result. error_estimate adds up
    * the discretisation error left at the finest level. With the
      differences d_n = K_n - K_n-1 and their ratio d_n / d_n-1 between
      1/32 and 1 (monotone, at a plausible rate; quadratic elements give
      about 1/16 on smooth solutions): max(|Richardson extrapolation of
      the last three - K|, |d_n|). Otherwise (reduced integration need
      not converge monotonically; at nu = 0.49 a difference of 1e-7 can
      be followed by one of 2.5e-6): max(2 |d_n|, |d_n-1| / 8);
    * the error of the fixed edge size (edge_check, one more run: the
      second finest level with 4 h_e; the singular element's error is
      proportional to h_e, so what is left at h_e is 1/3 of the change;
      smaller h_e are not used for this: at nu = 0.4999 round-off moves K
      by +1e-5 at h_e = 2.5e-6 mm);
    * the resolution of the 7 printed digits.
    Returns dict(K, error_estimate (N/mm), relative_error_estimate
    (error_estimate / K), richardson, ratio, edge_error, sequence=
    [axisymmetric_stiffness results], edge_run)."""
    sequence = []
    for level in levels:
        sequence.append(axisymmetric_stiffness(nu, level, workdir, element))
        if verbose:
            s = sequence[-1]
            print(f"  {element} nu = {nu} level {level}: {s['equations']:8d}"
                  f" equations, K = {s['K']:.8f} N/mm, {s['time_s']:6.1f} s,"
                  f" {s['memory_MB']:6.0f} MB", flush=True)
    ks = [s["K"] for s in sequence]
    if len(ks) < 3:
        raise ValueError("reference_stiffness needs at least three levels")
    limit, ratio = richardson(ks)
    d = [b - a for a, b in zip(ks, ks[1:])]
    if not math.isnan(limit) and ratio >= 1 / 32:
        error = max(abs(limit - ks[-1]), abs(d[-1]))
    else:
        error = max(2 * abs(d[-1]), abs(d[-2]) / 8)
    edge_error, edge_run = 0.0, None
    if edge_check and len(levels) > 1:
        coarser = sequence[-2]
        edge_run = axisymmetric_stiffness(nu, levels[-2], workdir, element,
                                          edge_size=4 * AXI_EDGE_SIZE)
        edge_error = abs(coarser["K"] - edge_run["K"]) / 3
        if verbose:
            change = edge_run["K"] - coarser["K"]
            print(f"  {element} nu = {nu} level {levels[-2]}, 4 h_e: K = "
                  f"{edge_run['K']:.8f} N/mm ({change:+.2e})", flush=True)
    error += edge_error + sequence[-1]["resolution"]
    return dict(K=ks[-1], error_estimate=error,
                relative_error_estimate=error / ks[-1], richardson=limit,
                ratio=ratio, edge_error=edge_error, sequence=sequence,
                edge_run=edge_run)


# --------------------------------------------------------------------------
# (B) 3D peer on an O-grid
# --------------------------------------------------------------------------
class OGrid:
    """The lateral O-grid (mirrors ssc::OGrid with a circular outer
    boundary): vertices (x, y), quadrilaterals (counter-clockwise), the
    edges lying on circles (with their radius) and the vertices of the
    outer circle."""

    def __init__(self, cells_around, edge_size, grading,
                 radius=RADIUS, circle=PUNCH):
        n = cells_around
        if n % 4:
            raise ValueError("cells_around must be a multiple of 4")
        self.n = n
        a, h, q = circle, edge_size, grading
        step = lambda r, k: min(h * q ** k, 2 * math.pi * r / n)
        inner = [a]
        k = 0
        while inner[-1] - step(inner[-1], k) >= 0.5 * a:
            inner.append(inner[-1] - step(inner[-1], k))
            k += 1
        self.core_half_width = 0.5 * inner[-1]
        self.n_inner_blend = max(1, round(
            (inner[-1] - self.core_half_width) /
            (2 * math.pi * inner[-1] / n)))
        outer = [a]
        k = 0
        while outer[-1] < radius:
            outer.append(outer[-1] + step(outer[-1], k))
            k += 1
        if len(outer) > 2 and \
                outer[-1] - radius > 0.5 * (outer[-1] - outer[-2]):
            outer.pop()
        scale = (radius - a) / (outer[-1] - a)
        outer = [a + (r - a) * scale for r in outer]
        outer[-1] = radius
        self.radii = inner[::-1] + outer[1:]
        self._build()

    def angle(self, j):
        return -0.25 * math.pi + 2 * math.pi * j / self.n

    def _build(self):
        n, m, w = self.n, self.n // 4, self.core_half_width
        coord = [w * math.tan(-0.25 * math.pi + 0.5 * math.pi * i / m)
                 for i in range(m + 1)]
        vertices = [(coord[i], coord[k]) for k in range(m + 1)
                    for i in range(m + 1)]
        quads = [(k * (m + 1) + i, k * (m + 1) + i + 1,
                  (k + 1) * (m + 1) + i + 1, (k + 1) * (m + 1) + i)
                 for k in range(m) for i in range(m)]
        boundary = [k * (m + 1) + i for k in range(m + 1)
                    for i in range(m + 1) if k in (0, m) or i in (0, m)]

        def on_square(j):
            c, s = math.cos(self.angle(j)), math.sin(self.angle(j))
            f = w / max(abs(c), abs(s))
            return c * f, s * f

        def on_circle(r, j):
            return r * math.cos(self.angle(j)), r * math.sin(self.angle(j))

        rows = []
        for i in range(self.n_inner_blend):
            t = i / self.n_inner_blend
            rows.append([tuple((1 - t) * p + t * c for p, c in zip(
                on_square(j), on_circle(self.radii[0], j)))
                for j in range(n)])
        rows += [[on_circle(r, j) for j in range(n)] for r in self.radii]
        # the first row is the core's boundary
        ids = []
        for x, y in rows[0]:
            ids.append(min(boundary, key=lambda v: (vertices[v][0] - x) ** 2
                           + (vertices[v][1] - y) ** 2))
        row_ids = [ids]
        for row in rows[1:]:
            row_ids.append(list(range(len(vertices),
                                      len(vertices) + len(row))))
            vertices += row
        self.arcs = {}  # (v0, v1) sorted -> radius, for edges on circles
        for k in range(len(rows) - 1):
            for j in range(n):
                jn = (j + 1) % n
                quads.append((row_ids[k][j], row_ids[k + 1][j],
                              row_ids[k + 1][jn], row_ids[k][jn]))
        for k, r in enumerate(self.radii):
            row = row_ids[self.n_inner_blend + k]
            for j in range(n):
                self.arcs[tuple(sorted((row[j], row[(j + 1) % n])))] = r
        self.vertices = np.array(vertices)
        self.quads = quads
        self.outer = set(row_ids[-1])
        x, y = self.vertices.T
        for qd in quads:  # counter-clockwise
            area = sum(x[qd[i]] * y[qd[(i + 1) % 4]] -
                       x[qd[(i + 1) % 4]] * y[qd[i]] for i in range(4))
            assert area > 0, "clockwise quadrilateral in the O-grid"

    def midside(self, v0, v1):
        """Midside node of an edge: on the circle for edges along one."""
        p, q = self.vertices[v0], self.vertices[v1]
        r = self.arcs.get(tuple(sorted((v0, v1))))
        if r is None:
            return 0.5 * (p + q)
        t = math.atan2(p[1], p[0]) + 0.5 * math.remainder(
            math.atan2(q[1], q[0]) - math.atan2(p[1], p[0]), 2 * math.pi)
        return np.array([r * math.cos(t), r * math.sin(t)])


def depth_levels(edge_size, grading, max_height=None, min_per_layer=2):
    """z of the slice boundaries, ascending from -DEPTH to 0: heights start
    at edge_size at the surface and grow by grading (at most max_height),
    continued through the layers; per layer a last height overshooting by
    more than half of it is dropped and the heights are scaled to the
    thickness; a layer with fewer than min_per_layer slices gets that many
    equal ones (one C3D20R through a soft layer locks at nu = 0.4999)."""
    height, z, top = edge_size, [0.0], 0.0
    for _, thickness, _ in LAYERS:
        steps, total = [], 0.0
        while total < thickness:
            steps.append(height)
            total += height
            height = min(height * grading, max_height or math.inf)
        if len(steps) > 1 and total - thickness > 0.5 * steps[-1]:
            total -= steps.pop()
        if len(steps) < min_per_layer:
            steps, total = [1.0] * min_per_layer, float(min_per_layer)
        for s in steps:
            z.append(z[-1] - s * thickness / total)
        top += thickness
        z[-1] = -top
    return np.array(z[::-1])


def peer_3d_input(nu, grid, z, element="C3D20R"):
    """The ccx input of the punch on the O-grid extruded to the slices z.
    Returns (text, n_nodes, n_elements)."""
    nv = len(grid.vertices)
    edges = {}
    for qd in grid.quads:
        for i in range(4):
            key = tuple(sorted((qd[i], qd[(i + 1) % 4])))
            if key not in edges:
                edges[key] = len(edges)
    ne2 = len(edges)
    mid2d = np.empty((ne2, 2))
    for (v0, v1), k in edges.items():
        mid2d[k] = grid.midside(v0, v1)
    nl = len(z)
    # node ids: corners (vertex, level), edge midsides (edge, level),
    # vertical midsides (vertex, slab)
    corner = lambda v, l: 1 + l * nv + v
    edge_node = lambda e, l: 1 + nl * nv + l * ne2 + e
    vertical = lambda v, l: 1 + nl * (nv + ne2) + l * nv + v
    L = ["*HEADING", f"bonded punch, 3D {element}, nu = {nu}", "*NODE"]
    for l in range(nl):
        L += [f"{corner(v, l)}, {_fmt(x)}, {_fmt(y)}, {_fmt(z[l])}"
              for v, (x, y) in enumerate(grid.vertices)]
    for l in range(nl):
        L += [f"{edge_node(e, l)}, {_fmt(x)}, {_fmt(y)}, {_fmt(z[l])}"
              for e, (x, y) in enumerate(mid2d)]
    for l in range(nl - 1):
        zm = 0.5 * (z[l] + z[l + 1])
        L += [f"{vertical(v, l)}, {_fmt(x)}, {_fmt(y)}, {_fmt(zm)}"
              for v, (x, y) in enumerate(grid.vertices)]
    L.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    bottoms = -np.cumsum([t for _, t, _ in LAYERS])
    elsets = {name: [] for name, _, _ in LAYERS}
    e = 0
    for l in range(nl - 1):
        layer = LAYERS[int(np.searchsorted(-bottoms,
                                           -0.5 * (z[l] + z[l + 1])))][0]
        for qd in grid.quads:
            es = [edges[tuple(sorted((qd[i], qd[(i + 1) % 4])))]
                  for i in range(4)]
            nodes = [corner(v, l) for v in qd] + \
                    [corner(v, l + 1) for v in qd] + \
                    [edge_node(k, l) for k in es] + \
                    [edge_node(k, l + 1) for k in es] + \
                    [vertical(v, l) for v in qd]
            e += 1
            L += _brick20(e, nodes)
            elsets[layer].append(e)
    L += _element_sets(elsets)
    outer_edges = [k for (v0, v1), k in edges.items()
                   if v0 in grid.outer and v1 in grid.outer]
    radius = np.hypot(*grid.vertices.T)
    mid_radius = np.hypot(*mid2d.T)
    top = nl - 1
    sets = {
        "BOTTOM": [corner(v, 0) for v in range(nv)] +
                  [edge_node(k, 0) for k in range(ne2)],
        "SIDE": [corner(v, l) for l in range(nl) for v in sorted(grid.outer)]
                + [edge_node(k, l) for l in range(nl) for k in outer_edges]
                + [vertical(v, l) for l in range(nl - 1)
                   for v in sorted(grid.outer)],
        "PUNCH": [corner(v, top) for v in range(nv) if radius[v] <= ON_PUNCH]
                 + [edge_node(k, top) for k in range(ne2)
                    if mid_radius[k] <= ON_PUNCH]}
    L += _node_sets_and_layers(sets, nu)
    L += ["*STEP", "*STATIC", "*BOUNDARY", "BOTTOM, 1, 3, 0.0",
          "SIDE, 1, 3, 0.0", "PUNCH, 1, 2, 0.0", f"PUNCH, 3, 3, {-INDENT!r}",
          "*NODE PRINT, NSET=PUNCH, TOTALS=ONLY", "RF", "*END STEP"]
    n_nodes = nl * (nv + ne2) + (nl - 1) * nv
    return "\n".join(L) + "\n", n_nodes, e


def peer_3d(nu, cells_around, edge_size, grading, workdir,
            max_height=None, element="C3D20R", reference=None,
            min_per_layer=2):
    """The 3D peer: element (C3D20R or C3D20) on the O-grid with
    cells_around cells around, radial size edge_size (mm) at r = a from both
    sides growing by grading, extruded in slices graded from edge_size at
    z = 0 (at most max_height; default: the spacing around at r = a, 2 pi a
    / n). One thread. Returns dict(K, equations, time_s, memory_MB,
    n_nodes, n_elements, solver, relative_error (if reference is given),
    and the mesh parameters)."""
    if max_height is None:
        max_height = 2 * math.pi * PUNCH / cells_around
    grid = OGrid(cells_around, edge_size, grading)
    z = depth_levels(edge_size, grading, max_height, min_per_layer)
    text, n_nodes, n_elements = peer_3d_input(nu, grid, z, element)
    job = f"peer_{element}_nu{nu}_n{cells_around}_h{edge_size}_q{grading}"
    out = run_ccx(workdir, job, text)
    fz = total_forces(out["dat"])[0][2]
    result = dict(K=-fz / INDENT, equations=out["equations"],
                  time_s=out["time_s"], cpu_s=out["cpu_s"],
                  memory_MB=out["memory_MB"],
                  n_nodes=n_nodes, n_elements=n_elements,
                  solver=out["solver"], element=element, nu=nu,
                  cells_around=cells_around, edge_size=edge_size,
                  grading=grading, max_height=max_height,
                  rings=len(grid.radii) + grid.n_inner_blend,
                  slices=len(z) - 1)
    if reference is not None:
        result["relative_error"] = result["K"] / reference - 1
    return result


# --------------------------------------------------------------------------
def main():
    parser = argparse.ArgumentParser(
        description="CalculiX reference and 3D peer of the layered bonded "
                    "punch (see the module docstring)")
    parser.add_argument("--nu", type=float, nargs="+",
                        default=[0.3, 0.49, 0.4999])
    parser.add_argument("--workdir", default=None,
                        help="scratch directory (default: a new one in /tmp)")
    parser.add_argument("--quick", action="store_true",
                        help="reference levels 0-2 only, 3D meshes up to "
                             "about 45k equations")
    parser.add_argument("--skip-3d", action="store_true")
    parser.add_argument("--full-integration", action="store_true",
                        help="also the CAX8 sequence and the C3D20 runs")
    parser.add_argument("--csv", default=None,
                        help="write the 3D peer rows to this file")
    args = parser.parse_args()
    workdir = args.workdir or tempfile.mkdtemp(prefix="calculix_punch_")
    print(f"ccx: {CCX}; work directory {workdir}", flush=True)

    print("\nForce convention of axisymmetric elements (ring force = 180 "
          "RF, axial component):")
    for case, element, ccx, exact in \
            check_axisymmetric_force_convention(workdir):
        print(f"  {case:34s} {element:5s} 180 RF = {ccx:12.7g}, closed "
              f"form {exact:12.7g}, ratio - 1 = {ccx / exact - 1:+.1e}")

    levels = REFERENCE_LEVELS[:3] if args.quick else REFERENCE_LEVELS
    print(f"\nAxisymmetric reference: CAX8R, h_e = {AXI_EDGE_SIZE} mm, "
          f"level n: g = {AXI_GROWTH} / 2^n, h_max = {AXI_MAX_SIZE} / 2^n",
          flush=True)
    references = {}
    for nu in args.nu:
        references[nu] = reference_stiffness(nu, workdir, levels,
                                             verbose=True)
        if args.full_integration:
            full = reference_stiffness(nu, workdir, levels[:3], "CAX8",
                                       edge_check=False, verbose=True)
            print(f"  CAX8 nu = {nu}: Richardson {full['richardson']:.8f} "
                  f"(ratio {full['ratio']:.3f})", flush=True)
    print(f"\n  {'nu':>6s} {'K N/mm':>12s} {'error est.':>10s} "
          f"{'relative':>9s} {'Richardson':>12s} {'ratio':>6s}  "
          "differences between levels / K")
    for nu, ref in references.items():
        ks = [s["K"] for s in ref["sequence"]]
        diffs = ", ".join(f"{(b - a) / ks[-1]:+.1e}"
                          for a, b in zip(ks, ks[1:]))
        rich = "n/a" if math.isnan(ref["richardson"]) \
            else f"{ref['richardson']:.8f}"
        print(f"  {nu:6g} {ref['K']:12.8f} {ref['error_estimate']:10.1e} "
              f"{ref['error_estimate'] / ref['K']:9.1e} {rich:>12s} "
              f"{ref['ratio']:6.3f}  {diffs}")

    if args.skip_3d:
        return
    meshes = [m for m in PEER_MESHES if not args.quick or m[1] >= 0.02]
    elements = ["C3D20R", "C3D20"] if args.full_integration else ["C3D20R"]
    rows = []
    print("\n3D peer, one thread (error against the reference above):")
    print(f"  {'element':7s} {'nu':>6s} {'n':>3s} {'h_e':>5s} {'q':>5s} "
          f"{'h_z max':>7s} {'rings':>5s} {'slices':>6s} {'equations':>9s} "
          f"{'K N/mm':>11s} {'error %':>8s} {'wall s':>7s} {'cpu s':>6s} "
          f"{'MB':>6s}")
    for nu in args.nu:
        for element in elements:
            for n, h, q, hz in meshes:
                p = peer_3d(nu, n, h, q, workdir, hz, element,
                            references[nu]["K"])
                rows.append(p)
                print(f"  {element:7s} {nu:6g} {n:3d} {h:5.3g} {q:5.3g} "
                      f"{hz:7.3g} {p['rings']:5d} {p['slices']:6d} "
                      f"{p['equations']:9d} {p['K']:11.7f} "
                      f"{100 * p['relative_error']:+8.3f} "
                      f"{p['time_s']:7.1f} {p['cpu_s']:6.1f} "
                      f"{p['memory_MB']:6.0f}", flush=True)
    print(f"  solver: {rows[0]['solver']}")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
