#!/usr/bin/python3
"""CalculiX (ccx 2.20) linear-elastic reference for the bonded rectangular
probe (45 x 8 mm, the MULTIS ultrasound probe's face) pressed on a
three-layer block: the stiffness K and each layer's strain under the
probe centre, converged by a sequence of graded meshes.

The problem (mm, N, MPa; z up, skin surface z = 0; linear elasticity):
block x in [-52.5, 52.5], y in [-34, 34], z in [-22.31, 0]; layers from
the top skin 1.655 (E = 0.05), fat 3.823 (0.02), muscle 16.832 (0.02),
interfaces z = -1.655 and -5.478; one Poisson ratio nu (0.49, the main
case, and 0.3). Bottom and the four lateral faces fixed (all components).
Rigid flat probe, bonded: every top node with |x| <= 22.5 (1 + 1e-10) and
|y| <= 4 (1 + 1e-10) gets u_x = u_y = 0, u_z = -d, d = 1 mm; the rest of
the top is traction-free. K = (total vertical reaction on the probe
nodes) / d, N/mm, of the full block. Layer strains under the centre
(positive = compressed), from u_z on the axis x = y = 0:
skin (u_z(-1.655) + d) / 1.655, fat (u_z(-5.478) - u_z(-1.655)) / 3.823,
muscle -u_z(-5.478) / 16.832.

Symmetry: the quarter x >= 0, y >= 0 is modelled, with u_x = 0 on x = 0
and u_y = 0 on y = 0; K is 4 times the quarter's total reaction (the
script says so in its output). --check-symmetry compares it with the full
block on a coarse mesh (level -2, 10.6k / 41.5k equations): K and the
strains agree to all printed digits (1.086337 N/mm at nu = 0.3).

Elements: C3D20R (20-node brick, reduced integration, 8 points) is the
main element; ccx 2.20 has no hybrid (C3D20H) element, and
calculix_punch.py found C3D20R converging cleanly at nu = 0.49 where
C3D20 (27 points) locks mildly. C3D20 is run at nu = 0.3 only, as a
cross-check.

Mesh: a structured tensor grid of 20-node bricks (midside nodes at the
edge midpoints), with node lines on x = 22.5 and y = 4 (the probe's
edges), on x = 0 and y = 0 (the symmetry planes, the axis), on the layer
interfaces and at z = 0. Sizes (class Sizes) at a distance s from a
singular line, s = |x - 22.5|, |y - 4| or -z:

    h(s) = min(h_e + g s, near + far s [, centre + slope t]),

a geometric grading of ratio about 1 + g from h_e = 5e-3 mm at the
probe's edges and at the surface, then sizes `near` growing slowly with
slope `far` (outside the probe, and in depth), or a cap inside the probe
(x_inner, y_inner); along x inside the probe the sizes shrink again
towards the centre plane x = 0 (centre + slope t, t = distance from x =
0), where the strains are read. Points equidistribute the integral of
1 / h (the construction of calculix_punch.graded_segment); at least two
cells per layer. The finest level (3) uses FINEST: g = 1.5 (x), 0.7 (y),
0.6 (z); x_inner 2.0, centre 0.6 + 0.3 t; y_inner 0.45; near 2.0 + 0.2 s
(x and y outside), 2.0 + 0.2 s (z). A level coarser multiplies every
size and slope (not h_e) by 1.25: levels 0-3 have 27k, 49k, 83k and 141k
equations (15 x 16 x 10 to 28 x 29 x 15 cells).
What the design runs showed (nu = 0.49 is the hard case): K is decided
by the gradings g (mostly in z, then y) and by the near sizes just
outside the probe (the squeezed fat flows out there), hardly by the
caps inside; the skin strain (a small difference, 0.013 at nu = 0.49)
by the sizes under the centre in x and y, not by the grading. The
grading towards the short edges x = +-22.5 matters little (g = 1.5).
The fixed h_e is checked by running the second finest level with the
cells at the singular lines merged with their neighbours (first cell
sizes times about 3 or more, the rest of the mesh unchanged); the singular
cells' error is taken as proportional to their size, so |change| / 2 is
left at h_e (3e-4 N/mm at nu = 0.49, 2e-4 at 0.3; nothing visible in
the strains). Checking h_e on a coarse level instead moves the whole
equidistributed mesh and overstates it (a 2.5 % skin-strain change at
level 0 with 4 h_e).

Convergence and error estimate (function converged): Richardson
extrapolation of the last three levels where the last three differences
have one sign and shrink (ratio in [1/32, 0.9]), its error the distance
it moves; otherwise the finest level with max(2 |d_n|, |d_n-1| / 8);
plus the h_e term and the 7-digit print resolution.

Results (2026-12-03, one thread, machine shared with other jobs; total
about 11.5 minutes, finest runs 116-132 s and 2.1 GB each):

    nu    element  K N/mm              skin          fat           muscle
    0.49  C3D20R   1.50464 +- 7.5e-4  0.013277      0.055683      0.045458
                   (5.0e-4 rel.)      +- 4.9e-5     +- 1.2e-5     +- 5e-6
    0.3   C3D20R   1.08431 +- 2.1e-4  0.022675      0.062888      0.042898
                                      +- 5e-6       +- 1.1e-5     +- 3e-6
    0.3   C3D20    1.08422 +- 6.4e-4  0.022673      0.062883      0.042899

K's differences shrink monotonically (nu = 0.49: -1.2e-3, -6.4e-4,
-3.1e-4 relative, ratio about 0.5 per level, i.e. only about second
order in the mesh scale; nu = 0.3: ratio 0.3). The skin strain at nu =
0.49 is not monotone (-0.87 %, +0.85 %, +0.18 %), hence its larger
estimate (3.7e-3 relative); every other strain is within 2.2e-4. C3D20
and C3D20R agree at nu = 0.3 (K 8e-5 apart, strains 1e-6 to 5e-6), both
from above; C3D20 converges more slowly in K (ratio 0.53).

What this relies on in CalculiX (see calculix_punch.py, where these were
verified): *BOUNDARY with prescribed nonzero displacements on a node set;
*NODE PRINT, NSET=PROBE, TOTALS=ONLY with RF, whose summed reaction ccx
writes to the .dat file (7 significant digits; the sign is that of the
force on the body, so K = -4 F_z / d); *NODE PRINT of U for the two axis
nodes (7 significant digits); ccx's C3D20 node numbering (corners of the
lower, then of the upper face counter-clockwise, midsides of their edges,
then the vertical midsides; a 20-node element's data line continued on a
second line); *STATIC with SPOOLES' direct solver, the only one in this
build. Runs: OMP_NUM_THREADS = CCX_NPROC_EQUATION_SOLVER = 1, niced; wall
time of the ccx process; peak memory from /usr/bin/time -v. Running ccx
and reading its total forces: calculix_punch.py's run_ccx and
total_forces (run it with /usr/bin/python3, whose numpy calculix_punch
needs).

Run (writes benchmarks/identification/results/calculix_probe.csv: nu,
element, level, equations, K_N_per_mm, strain_skin, strain_fat,
strain_muscle, wall_s; prints a Markdown table and the converged values):

    /usr/bin/python3 benchmarks/identification/calculix_probe.py
        [--nu 0.49 0.3] [--levels 0 1 2 3] [--no-full-integration]
        [--no-edge-check] [--check-symmetry] [--workdir DIR] [--csv FILE]
"""
import argparse
import csv
import math
import os
import re
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "common"))
from calculix_punch import (CCX, _brick20, _element_sets, _fmt,  # noqa: E402
                            _lines, run_ccx, total_forces)

# the problem (mm, N, MPa)
HALF_X, HALF_Y = 52.5, 34.0          # block half sizes
PROBE_X, PROBE_Y = 22.5, 4.0         # probe half sizes (face 45 x 8)
LAYERS = [("SKIN", 1.655, 0.05), ("FAT", 3.823, 0.02),
          ("MUSCLE", 16.832, 0.02)]  # (name, thickness, E), from the top
DEPTH = 22.31
INTERFACES = (-1.655, -5.478)
INDENT = 1.0                         # d, mm
TOL = 1 + 1e-10

# mesh (see Sizes and mesh): sizes at the finest level; a level coarser
# multiplies every entry (sizes and slopes) by FACTOR; EDGE_SIZE is fixed
EDGE_SIZE = 5e-3
FINEST = dict(gx=1.5, gy=0.7, gz=0.6, x_inner=2.0, x_centre=0.6,
              x_slope=0.3, y_inner=0.45, near=2.0, far=0.2, z_near=2.0,
              z_far=0.2)
FINEST_LEVEL = 3
FACTOR = 1.25
LEVELS = (0, 1, 2, 3)
CSV_FIELDS = ["nu", "element", "level", "equations", "K_N_per_mm",
              "strain_skin", "strain_fat", "strain_muscle", "wall_s"]


# --------------------------------------------------------------------------
# running ccx: calculix_punch's helpers (one thread, niced, peak memory)
# --------------------------------------------------------------------------
def displacements(dat, nset):
    """{node: (ux, uy, uz)} of the 'displacements' block of set nset."""
    m = re.search(r"displacements \(vx,vy,vz\) for set " + nset +
                  r" and time\s+\S+\s*\n\s*\n((?:\s*\d+(?:\s+\S+){3}\s*\n)+)",
                  dat + "\n")
    if not m:
        raise RuntimeError(f"no displacements of set {nset} in the .dat")
    out = {}
    for line in m.group(1).strip().splitlines():
        v = line.split()
        out[int(v[0])] = tuple(float(x) for x in v[1:4])
    return out


# --------------------------------------------------------------------------
# the mesh
# --------------------------------------------------------------------------
class Sizes:
    """Element sizes at a distance s from a singular line (the probe's
    edge or the skin surface):

        h(s) = min(edge_size + growth s, near + far s, centre + slope t),

    t = length - s the distance from the far end of the segment (the
    model's centre plane; the last term only if centre is given): a
    geometric grading of ratio about 1 + growth from edge_size, then sizes
    near growing with slope far, and sizes shrinking again towards the
    centre plane, where the strains are read."""

    def __init__(self, edge_size, growth, near, far=0.0, centre=None,
                 slope=0.0):
        self.e, self.g, self.n, self.f = edge_size, growth, near, far
        self.c, self.k = centre, slope

    def h(self, s, length):
        h = min(self.e + self.g * s, self.n + self.f * s)
        if self.c is not None:
            h = min(h, self.c + self.k * (length - s))
        return h

    def segment(self, s0, s1, min_cells=1, length=None):
        """Points from s0 to s1 (0 <= s0 < s1): the number of intervals is
        the integral of 1 / h rounded up (at least min_cells), the points
        equidistribute that integral (as calculix_punch.graded_segment;
        here by the midpoint rule on 4000 subintervals, geometric in s)."""
        length = s1 if length is None else length
        m = 4000
        a = math.log(self.e / 16)
        b = math.log(s1 + self.e / 16)
        t = [math.exp(a + (b - a) * k / m) - self.e / 16
             for k in range(m + 1)]
        t = [min(max(v, s0), s1) for v in t]
        t[0], t[-1] = s0, s1
        G = [0.0]
        for u, v in zip(t, t[1:]):
            G.append(G[-1] + (v - u) / self.h(0.5 * (u + v), length))
        n = max(min_cells, math.ceil(G[-1] - 1e-9))
        pts, j = [s0], 0
        for k in range(1, n):
            target = G[-1] * k / n
            while G[j + 1] < target:
                j += 1
            w = (target - G[j]) / (G[j + 1] - G[j])
            pts.append(t[j] + w * (t[j + 1] - t[j]))
        pts.append(s1)
        return pts


def axis_points(edge, half, inner, outer):
    """Ascending points on [0, half], graded towards edge from both sides
    (Sizes inner on [0, edge], outer on [edge, half])."""
    left = inner.segment(0.0, edge, length=edge)
    right = outer.segment(0.0, half - edge)
    pts = sorted([edge - s for s in left] + [edge + s for s in right[1:]])
    pts[0], pts[-1] = 0.0, half
    return pts


def depth_points(sizes):
    """Ascending z from -DEPTH to 0, graded from the surface (Sizes of the
    depth), with points on the interfaces and at least two cells per
    layer."""
    z, top = [0.0], 0.0
    for _, thickness, _ in LAYERS:
        z += [-s for s in sizes.segment(top, top + thickness, 2)[1:]]
        top += thickness
    z[-1] = -DEPTH
    return sorted(z)


def mesh(level, edge_size=EDGE_SIZE, factor=FACTOR, coarsen_edge=False,
         **sizes):
    """Corner coordinates (x, y, z ascending) of the quarter model at a
    level: every entry of FINEST (sizes overrides) times
    factor^(FINEST_LEVEL - level); edge_size fixed. coarsen_edge: without
    the first point next to each singular line (x = 22.5 from both sides,
    y = 4 from both sides, z = 0), so that the cells at the probe's edge
    are merged with their neighbours and the rest of the mesh is the same;
    then also returns the smallest ratio (new size / old size) of the
    cells at the singular lines."""
    p = dict(FINEST, **sizes)
    s = factor ** (FINEST_LEVEL - level)
    p = {k: v * s for k, v in p.items()}
    e = edge_size
    x = axis_points(PROBE_X, HALF_X,
                    Sizes(e, p["gx"], p["x_inner"], 0.0, p["x_centre"],
                          p["x_slope"]),
                    Sizes(e, p["gx"], p["near"], p["far"]))
    y = axis_points(PROBE_Y, HALF_Y, Sizes(e, p["gy"], p["y_inner"]),
                    Sizes(e, p["gy"], p["near"], p["far"]))
    z = depth_points(Sizes(e, p["gz"], p["z_near"], p["z_far"]))
    if not coarsen_edge:
        return x, y, z
    ratios = []

    def drop(pts, k, direction):
        first, second = pts[k + direction], pts[k + 2 * direction]
        ratios.append(abs(second - pts[k]) / abs(first - pts[k]))
        return [v for i, v in enumerate(pts) if i != k + direction]

    kx = x.index(PROBE_X)
    x = drop(drop(x, kx, +1), kx, -1)
    ky = y.index(PROBE_Y)
    y = drop(drop(y, ky, +1), ky, -1)
    z = drop(z, len(z) - 1, -1)
    return x, y, z, min(ratios)


def probe_input(nu, x, y, z, element="C3D20R", full=False):
    """The ccx input on the tensor grid of corner coordinates x, y (from 0
    to the half sizes) and z: the quarter model x >= 0, y >= 0 with
    symmetry conditions, or (full) the whole block with x and y mirrored.
    Returns (text, n_nodes, n_elements)."""
    if full:
        x = [-v for v in reversed(x[1:])] + list(x)
        y = [-v for v in reversed(y[1:])] + list(y)

    def with_midpoints(c):
        return [c[i // 2] if i % 2 == 0 else 0.5 * (c[i // 2] + c[i // 2 + 1])
                for i in range(2 * len(c) - 1)]

    X, Y, Z = with_midpoints(x), with_midpoints(y), with_midpoints(z)
    NX, NY, NZ = len(X), len(Y), len(Z)
    ids = {}
    L = ["*HEADING", f"bonded probe 45 x 8 on three layers, "
         f"{'full' if full else 'quarter'}, {element}, nu = {nu}", "*NODE"]
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                if (i % 2) + (j % 2) + (k % 2) <= 1:  # 20-node serendipity
                    n = len(ids) + 1
                    ids[i, j, k] = n
                    L.append(f"{n}, {_fmt(X[i])}, {_fmt(Y[j])}, "
                             f"{_fmt(Z[k])}")
    L.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    bottoms = [-sum(t for _, t, _ in LAYERS[:m + 1])
               for m in range(len(LAYERS))]
    elsets = {name: [] for name, _, _ in LAYERS}
    e = 0
    for kk in range(len(z) - 1):
        zm = 0.5 * (z[kk] + z[kk + 1])
        layer = next(LAYERS[m][0] for m in range(len(LAYERS))
                     if zm > bottoms[m])
        for jj in range(len(y) - 1):
            for ii in range(len(x) - 1):
                i, j, k = 2 * ii, 2 * jj, 2 * kk
                # ccx's C3D20 numbering: corners of the lower face (z) and
                # of the upper face counter-clockwise, midsides of their
                # edges, then the vertical edges' midsides
                quad = [(i, j), (i + 2, j), (i + 2, j + 2), (i, j + 2)]
                mids = [(i + 1, j), (i + 2, j + 1), (i + 1, j + 2),
                        (i, j + 1)]
                nodes = [ids[a, b, k] for a, b in quad] + \
                        [ids[a, b, k + 2] for a, b in quad] + \
                        [ids[a, b, k] for a, b in mids] + \
                        [ids[a, b, k + 2] for a, b in mids] + \
                        [ids[a, b, k + 1] for a, b in quad]
                e += 1
                L += _brick20(e, nodes)
                elsets[layer].append(e)
    L += _element_sets(elsets)
    i0 = X.index(0.0)
    j0 = Y.index(0.0)
    k1 = min(range(NZ), key=lambda k: abs(Z[k] - INTERFACES[0]))
    k2 = min(range(NZ), key=lambda k: abs(Z[k] - INTERFACES[1]))
    assert abs(Z[k1] - INTERFACES[0]) < 1e-9 and \
        abs(Z[k2] - INTERFACES[1]) < 1e-9
    assert any(abs(v - PROBE_X) < 1e-12 for v in X) and \
        any(abs(v - PROBE_Y) < 1e-12 for v in Y)
    side_i = (0, NX - 1) if full else (NX - 1,)
    side_j = (0, NY - 1) if full else (NY - 1,)
    sets = {
        "BOTTOM": [n for (i, j, k), n in ids.items() if k == 0],
        "SIDES": [n for (i, j, k), n in ids.items()
                  if i in side_i or j in side_j],
        "PROBE": [n for (i, j, k), n in ids.items() if k == NZ - 1 and
                  abs(X[i]) <= PROBE_X * TOL and abs(Y[j]) <= PROBE_Y * TOL],
        "AXIS1": [ids[i0, j0, k1]],
        "AXIS2": [ids[i0, j0, k2]]}
    if not full:
        sets["SYMX"] = [n for (i, j, k), n in ids.items() if i == 0]
        sets["SYMY"] = [n for (i, j, k), n in ids.items() if j == 0]
    for name, nodes in sets.items():
        L.append(f"*NSET, NSET={name}")
        L += _lines(sorted(nodes))
    for name, _, E in LAYERS:
        L += [f"*MATERIAL, NAME=M{name}", "*ELASTIC", f"{E!r}, {nu!r}",
              f"*SOLID SECTION, ELSET={name}, MATERIAL=M{name}"]
    L += ["*STEP", "*STATIC", "*BOUNDARY", "BOTTOM, 1, 3, 0.0",
          "SIDES, 1, 3, 0.0"]
    if not full:
        L += ["SYMX, 1, 1, 0.0", "SYMY, 2, 2, 0.0"]
    L += ["PROBE, 1, 2, 0.0", f"PROBE, 3, 3, {-INDENT!r}",
          "*NODE PRINT, NSET=PROBE, TOTALS=ONLY", "RF",
          "*NODE PRINT, NSET=AXIS1", "U",
          "*NODE PRINT, NSET=AXIS2", "U", "*END STEP"]
    return "\n".join(L) + "\n", len(ids), e


def probe_run(nu, level, workdir, element="C3D20R", full=False,
              edge_size=EDGE_SIZE, coarsen_edge=False, **sizes):
    """One level (see mesh): dict(nu, element, level, equations,
    K_N_per_mm, strain_skin, strain_fat, strain_muscle, wall_s, memory_MB,
    cells, edge_size, edge_ratio (coarsen_edge only)). K is 4 times the
    quarter model's total vertical reaction on the probe nodes (the full
    model's, if full) over d."""
    ratio = None
    if coarsen_edge:
        x, y, z, ratio = mesh(level, edge_size=edge_size, coarsen_edge=True,
                              **sizes)
    else:
        x, y, z = mesh(level, edge_size=edge_size, **sizes)
    text, n_nodes, n_elements = probe_input(nu, x, y, z, element, full)
    tag = "".join(f"_{k}{v}" for k, v in sorted(sizes.items()))
    job = (f"probe_{element}_nu{nu}_l{level}_h{edge_size}"
           f"{'_full' if full else ''}{'_coarse_edge' if ratio else ''}"
           f"{tag}")
    out = run_ccx(workdir, job, text)
    fz = total_forces(out["dat"])[0][2]
    uz1 = next(iter(displacements(out["dat"], "AXIS1").values()))[2]
    uz2 = next(iter(displacements(out["dat"], "AXIS2").values()))[2]
    return dict(nu=nu, element=element, level=level,
                equations=out["equations"],
                K_N_per_mm=-(1 if full else 4) * fz / INDENT,
                strain_skin=(uz1 + INDENT) / LAYERS[0][1],
                strain_fat=(uz2 - uz1) / LAYERS[1][1],
                strain_muscle=-uz2 / LAYERS[2][1],
                wall_s=out["time_s"], memory_MB=out["memory_MB"],
                cells=(len(x) - 1, len(y) - 1, len(z) - 1),
                edge_size=edge_size, edge_ratio=ratio)


# --------------------------------------------------------------------------
# convergence
# --------------------------------------------------------------------------
QUANTITIES = ["K_N_per_mm", "strain_skin", "strain_fat", "strain_muscle"]


def converged(values, edge_error, resolution):
    """The converged value of a sequence of levels and its error estimate.

    With the differences d_n = v_n - v_n-1: if the last three differences
    have one sign and the ratio r = d_n / d_n-1 is in [1/32, 0.9]
    (monotone, shrinking), the Richardson extrapolation v_n + d_n r /
    (1 - r), with the distance it moves from v_n as its error (the
    extrapolation may be wrong by as much as it corrects). Otherwise the
    finest value with max(2 |d_n|, |d_n-1| / 8) (the rule of
    calculix_punch.reference_stiffness for sequences that do not shrink
    monotonically). Added: edge_error (the fixed edge size's error, from
    the edge check) and the print resolution. Returns (value, error,
    ratio, extrapolated)."""
    d = [b - a for a, b in zip(values, values[1:])]
    ratio = d[-1] / d[-2] if d[-2] != 0 else float("nan")
    one_sign = all(v > 0 for v in d[-3:]) or all(v < 0 for v in d[-3:])
    if one_sign and 1 / 32 <= ratio <= 0.9:
        value = values[-1] + d[-1] * ratio / (1 - ratio)
        error = abs(value - values[-1])
        extrapolated = True
    else:
        value = values[-1]
        error = max(2 * abs(d[-1]), abs(d[-2]) / 8)
        extrapolated = False
    return value, error + edge_error + resolution, ratio, extrapolated


def sequence(nu, element, workdir, levels=LEVELS, edge_check=True,
             verbose=True):
    """The levels of one (nu, element) and the edge check: the second
    finest level again with the cells at the singular lines merged with
    their neighbours (mesh(coarsen_edge=True); their sizes grow by a
    factor r of about 3 or more). The singular cells' error is taken as
    proportional to their size (as calculix_punch found for the round
    punch), so what is left at h_e is |change| / (r - 1). Returns (rows,
    edge_row, summary: quantity -> (value, error, ratio, extrapolated,
    edge_error))."""
    rows = []
    for level in levels:
        r = probe_run(nu, level, workdir, element)
        rows.append(r)
        if verbose:
            print(f"  {element:6s} nu = {nu:<5g} level {level}: "
                  f"{r['equations']:7d} equations, cells {r['cells']}, "
                  f"K = {r['K_N_per_mm']:.7f}, strains {r['strain_skin']:.6f}"
                  f" {r['strain_fat']:.6f} {r['strain_muscle']:.6f}, "
                  f"{r['wall_s']:5.1f} s, {r['memory_MB']:5.0f} MB",
                  flush=True)
    edge = None
    base = rows[-2] if len(rows) > 1 else rows[-1]
    if edge_check:
        edge = probe_run(nu, base["level"], workdir, element,
                         coarsen_edge=True)
        if verbose:
            print(f"  {element:6s} nu = {nu:<5g} level {base['level']} "
                  f"with the edge cells merged (sizes x "
                  f"{edge['edge_ratio']:.2f} or more): "
                  f"K = {edge['K_N_per_mm']:.7f}, strains "
                  f"{edge['strain_skin']:.6f} {edge['strain_fat']:.6f} "
                  f"{edge['strain_muscle']:.6f}, {edge['wall_s']:5.1f} s",
                  flush=True)
    summary = {}
    for q in QUANTITIES:
        values = [r[q] for r in rows]
        edge_error = abs(edge[q] - base[q]) / (edge["edge_ratio"] - 1) \
            if edge else 0.0
        # 7 printed digits: of the force, or of the displacements (u ~ d)
        resolution = 5e-7 * abs(values[-1]) if q == "K_N_per_mm" \
            else 2 * 5e-7 * INDENT / LAYERS[QUANTITIES.index(q) - 1][1]
        summary[q] = converged(values, edge_error, resolution) + \
            (edge_error,)
    return rows, edge, summary


# --------------------------------------------------------------------------
def main():
    parser = argparse.ArgumentParser(
        description="CalculiX linear-elastic reference of the bonded "
                    "45 x 8 mm probe on three layers (see the docstring)")
    parser.add_argument("--nu", type=float, nargs="+", default=[0.49, 0.3])
    parser.add_argument("--levels", type=int, nargs="+", default=LEVELS)
    parser.add_argument("--no-full-integration", action="store_true",
                        help="skip the C3D20 cross-check at nu = 0.3")
    parser.add_argument("--no-edge-check", action="store_true")
    parser.add_argument("--check-symmetry", action="store_true",
                        help="also compare quarter and full model on a "
                             "coarse mesh")
    parser.add_argument("--workdir", default=None)
    parser.add_argument("--csv", default=os.path.join(
        HERE, "results", "calculix_probe.csv"))
    args = parser.parse_args()
    workdir = args.workdir or tempfile.mkdtemp(prefix="calculix_probe_")
    print(f"ccx: {CCX}; work directory {workdir}; one thread", flush=True)
    start = time.perf_counter()

    if args.check_symmetry:
        q = probe_run(0.3, -2, workdir)
        f = probe_run(0.3, -2, workdir, full=True)
        print("Symmetry check (nu = 0.3, level -2): quarter x 4 vs full: "
              + ", ".join(f"{k} {q[k]:.7g} / {f[k]:.7g}"
                          for k in QUANTITIES), flush=True)

    runs = [(nu, "C3D20R") for nu in args.nu]
    if 0.3 in args.nu and not args.no_full_integration:
        runs.append((0.3, "C3D20"))
    rows, summaries = [], {}
    for nu, element in runs:
        print(f"\n{element}, nu = {nu}:", flush=True)
        r, edge, summary = sequence(nu, element, workdir, args.levels,
                                    not args.no_edge_check)
        rows += r
        summaries[nu, element] = (r, edge, summary)

    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_FIELDS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{r[k]:.6g}" if k == "wall_s" else
                            f"{r[k]:.8g}" if isinstance(r[k], float) else
                            r[k]) for k in CSV_FIELDS})
    print(f"\nwrote {args.csv}\n")

    print("| nu | element | level | equations | K (N/mm) | skin | fat | "
          "muscle | wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['nu']:g} | {r['element']} | {r['level']} | "
              f"{r['equations']} | {r['K_N_per_mm']:.6f} | "
              f"{r['strain_skin']:.6f} | {r['strain_fat']:.6f} | "
              f"{r['strain_muscle']:.6f} | {r['wall_s']:.1f} |")
    print("\nRelative differences between successive levels:")
    for (nu, element), (r, edge, summary) in summaries.items():
        for q in QUANTITIES:
            v = [x[q] for x in r]
            diffs = ", ".join(f"{(b - a) / v[-1]:+.1e}"
                              for a, b in zip(v, v[1:]))
            print(f"  {element:6s} nu = {nu:<5g} {q:14s} {diffs}")
    print("\nConverged values (Richardson extrapolation of the last three "
          "levels where the differences shrink monotonically, else the "
          "finest level; error estimate includes the edge-size and print "
          "resolution terms):")
    for (nu, element), (r, edge, summary) in summaries.items():
        for q in QUANTITIES:
            value, error, ratio, extrapolated, edge_error = summary[q]
            how = "Richardson" if extrapolated else "finest"
            print(f"  {element:6s} nu = {nu:<5g} {q:14s} {value:.6f} "
                  f"+- {error:.1e} ({error / abs(value):.1e} relative; "
                  f"ratio of last differences {ratio:+.2f}, {how}; edge "
                  f"term {edge_error:.1e})")
    print(f"\ntotal wall time {time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    main()
