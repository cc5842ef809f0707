#!/usr/bin/python3
"""An independent CalculiX reference for linear visco-elastic indentation:
the force relaxation of the layered, bonded flat punch whose fat layers
(SAT, DAT) are a standard linear solid (one deviatoric Prony term), the
other layers elastic.

The law (the other code's): instantaneous shear modulus G0 = E / (2 (1 +
nu)), E = 0.001 MPa, nu = 0.49, the bulk modulus K0 = E / (3 (1 - 2 nu))
purely elastic, and the shear relaxation function

    G(t) = G0 (g_inf + g exp(-t / tau)),  g = 0.39, g_inf = 0.61, tau = 20 s.

Construction in ccx 2.20 (no Prony series there): two element sets on the
SAME nodes with the same connectivity (parallel rheology, stiffnesses and
internal forces add up):
- an elastic part: shear G_a = g_inf G0, bulk K_a = K0 - K_b;
- a Maxwell part: shear G_b = g G0, bulk K_b = G_b (its volumetric response
  is elastic and adds to K_a), *ELASTIC plus *CREEP, LAW=NORTON with n = 1,
  m = 0: deviatoric creep rate (3/2) A s, so a shear stress relaxes as
  exp(-3 G_b A t): A = 1 / (3 G_b tau).
Each (G, K) goes to ccx as E = 9 K G / (3 K + G), nu = (3 K - 2 G) / (2 (3
K + G)).

What ccx 2.20 does with this (read in the published ccx source of that
era, creeps.f, incplas.f, viscos.f, checkconvergence.c, and tested on
the installed 2.20):
- *CREEP without *PLASTIC: a zero yield stress without hardening is
  assumed (creeps.f sets a flat isotropic hardening curve at 0), so the
  whole deviatoric stress drives the creep; the material becomes
  nonlinear (Newton iterations, iperturb = 3). Creep is only active in
  *VISCO steps: in a *STATIC step the same material is elastic (checked:
  the *STATIC run with *CREEP gives the elastic force).
- The creep increment is backward Euler (incplas.f: the rate at the end
  of the increment; for n = 1 its local Newton is exact). The homogeneous
  check below reproduces the backward-Euler recursion of the Maxwell branch
  to the 7 printed digits (a few 1e-7), and it is exactly linear in the
  strain amplitude (1e-9 to 0.1) without NLGEOM.
- *VISCO needs CETOL (mandatory), and CETOL also enters the convergence
  test of *VISCO steps even with DIRECT (the change of the creep strain
  increment within the increment must stay below it): with CETOL = 1e-3
  and d = 0.5 mm the punch run stopped ("solution seems to diverge")
  although the residual was zero. CETOL = 1e30 switches that test off;
  DIRECT with the given increment gives fixed increments.
- Pitfall 1: in *VISCO steps a *BOUNDARY without amplitude is applied as
  a step at the start of the step, not ramped. The ramp is an *AMPLITUDE
  with TIME=TOTAL TIME (0 at t = 0, 1 from t = 0.1 s on) on the punch
  displacement.
- Pitfall 2: incplas.f treats a trial stress norm below 1e-10 (absolute,
  stress units) as elastic, i.e. no creep below 1e-10 MPa. With the true
  moduli (E = 0.001 MPa) and a shear of 1e-5 the cube's force at 80 s was
  1.5 % off (creep stopped as the stress decayed). All moduli are
  therefore multiplied by SCALE = 1e6 (A divided by it) and the forces
  divided by it: the problem is linear, the scaling exact.
- At least two Newton iterations per increment (checkconvergence.c
  demands iit > 1). On the punch the second iteration corrects by 2e-11
  mm (the first moved 1.5e-3 mm), a third one would by 4e-15 mm, and
  tightening all *CONTROLS field tolerances to 1e-12 changed no printed
  digit. Each iteration is one SPOOLES factorisation.
- Overlapping element sets on the same nodes are accepted for CAX8R
  (and C3D8); the number of equations does not change.

Checks and results (2026-12-07, ccx 2.20, one thread):
1. Homogeneous cube (one C3D8 twice, on the same nodes; simple shear with
   every node prescribed, and uniaxial stress with symmetry planes and
   free lateral faces, which couples K and G and so checks the bulk
   split), strain 1e-3 ramped over 0.1 s and held to 80 s. Closed forms:
   for a modulus M(t) = M_inf + (M_0 - M_inf) exp(-t / T) and the strain
   ramped to 1 over t_r, the stress is the convolution of M with the
   ramp's strain rate, (M_inf t + (M_0 - M_inf) T (1 - exp(-t / T))) / t_r
   during the ramp and M_inf + (M_0 - M_inf) (T / t_r) (exp(t_r / T) - 1)
   exp(-t / T) after it. Shear: M = G(t). Uniaxial stress with elastic K:
   E~(s) = 9 K G~(s) / (3 K + G~(s)) is again a standard linear solid,
   E_0 = 9 K G0 / (3 K + G0), E_inf = 9 K g_inf G0 / (3 K + g_inf G0),
   T = tau (3 K + G0) / (3 K + g_inf G0). Increments: the segments [0,
   0.1], [0.1, 2], [2, 5], [5, 10], [10, 20], [20, 40], [40, 80] s, n
   fixed increments each, n = 1, 2, 4, ..., 256. The largest relative
   error over the seven times halves with n (observed order 0.995 to 1.08
   from n = 64, 128, 256): 4.4e-2 at n = 1, 3.3e-3 at n = 16, 8.3e-4 at
   n = 64 (below 1e-3 from there), 2.1e-4 at n = 256, shear and uniaxial
   alike; the Richardson extrapolation 2 F(256) - F(128) is within 4.3e-7
   (shear) and 4.2e-7 (uniaxial) of the closed forms. ccx reproduces the
   backward-Euler recursion of the Maxwell branch to 2e-7 to 4.5e-7 (a
   few units of the 7th printed digit) for every n.
2. Punch (calculix_punch's geometry, meshes, force convention 180 RF,
   axial component only), CAX8R, the fat elements duplicated (same nodes,
   new numbers) into SATB, DATB for the Maxwell part. Overlap check: with
   the Maxwell part elastic (no *CREEP, so G(t) = G0) and with *CREEP in a
   *STATIC step the force equals calculix_punch's elastic K d to -1.0e-7
   (level 0) and 0 (level 1), i.e. to the printed digits. d = 0.5 mm
   ramped over 0.1 s (linear, no NLGEOM), held to 80 s, n increments per
   segment as above.
   Q(t) = F(t) / (K_L d), K_L the elastic stiffness of the same mesh
   level L, and the ratio F(t) / F(0.1) are converged
   - in time on level 0 (16k equations) with n = 2, 4, 8, 16, 32 (14 to
     224 increments): first order, observed orders 0.89 to 1.00 (0.97 to
     1.00 from n = 8, 16, 32); two-stage Richardson on n = 8, 16, 32
     (first, then second order). F(80) at n = 32 is still 4.1e-4 above
     the limit, at n = 2 6.5e-3;
   - in mesh by n = 1 on levels 0, 1, 2 (16k, 58k, 208k equations) plus
     the change of the level 0 -> 1 difference with n (n = 1, 2, 4 on
     level 1, extrapolated to first order). Level 0 -> 2 changes Q and the
     ratio by +7e-8 (0.1 s) to +8.6e-6 (80 s); level 1 -> 2 alone by up
     to 4.9e-6; the n-dependence of the mesh difference is below 7e-7.
     The relaxed state (the long-term elastic problem, fat shear g_inf G0)
     has the same mesh behaviour and one level more: its force changes by
     -3.9e-5, +6.2e-6, -1.4e-6 from level 0 to 1, 2, 3.
   F(t) = Q(t) K_ref d with K_ref = 0.03524287 N/mm, calculix_punch's
   reference stiffness on levels 0-2 (its error estimate 6.0e-6
   relative).

   Uncertainty = |second-stage Richardson correction| (time) + |Q or
   ratio on level 2 - level 1| + |last change of the mesh difference
   with n| (mesh) + the rounding of the 7 printed digits (2e-6 relative
   for Q, 3e-6 for the ratio, two standard deviations through the
   extrapolation weights), for Q and the ratio separately; for F the
   relative uncertainty of K_ref is added. Result:

      t s    F N          +-        F/F(0.1)     +-
      0.1    0.01761467   1.4e-7    1            -
      2      0.01736865   1.5e-7    0.9860328    3.6e-6
      5      0.01702007   1.6e-7    0.9662436    4.5e-6
      10     0.01653279   1.9e-7    0.9385804    6.1e-6
      20     0.01582836   2.4e-7    0.8985896    9.5e-6
      40     0.01507932   3.1e-7    0.8560659    1.4e-5
      80     0.01462732   2.1e-7    0.8304052    7.7e-6

   F(0.1) / (K_ref d) = 0.9996163 (the ramp already relaxes 3.8e-4); the
   long-term limit is F / F(0.1) = 0.824332 (level 1), so at 80 s 3.5 %
   of the relaxing part is left (an apparent time constant of about 24 s,
   between tau and tau / g_inf).

Run (about 10 minutes on one core, 5.3 GB for the level-3 run; ccx
niced, one thread; work files in a new directory under /tmp unless
--workdir):

    /usr/bin/python3 \
        benchmarks/finite_strain_vs_calculix/visco_relaxation_calculix.py
        [--workdir DIR] [--quick]

writes results/visco_relaxation_calculix.csv (time_s, force_N,
force_ratio, uncertainty_force, uncertainty_ratio) and
results/visco_relaxation_calculix_checks.csv (the homogeneous check and
every punch run: check, case, level, n, time_s, value, closed_form,
relative_error). --quick (about 2 minutes) runs shorter sequences
(level 0 n = 1-8, levels 0-1) and writes nothing.
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
import calculix_punch as cp  # noqa: E402

RESULTS = os.path.join(HERE, "results", "visco_relaxation_calculix.csv")
CHECKS = os.path.join(HERE, "results",
                      "visco_relaxation_calculix_checks.csv")

NU = 0.49
G_REL, TAU, T_RAMP = 0.39, 20.0, 0.1   # Prony term, ramp time s
G_INF = 1 - G_REL
TIMES = (T_RAMP, 2.0, 5.0, 10.0, 20.0, 40.0, 80.0)  # segment ends, s
FAT = ("SAT", "DAT")
E_FAT = dict((name, E) for name, _, E in cp.LAYERS)["SAT"]
SCALE = 1e6          # all moduli times SCALE in ccx, forces divided by it
CETOL = "1e30"       # switches ccx's creep-strain convergence test off
# the rounding of the 7 printed digits (half a unit: 2.8e-7 to 3.6e-7 of
# forces of 0.014 to 0.018 N) through the weights of the extrapolations
# (root sum of squares about 5 for Q, 7 for the ratio, which has two
# rounded forces per run), two standard deviations of a uniform rounding
RESOLUTION = {"Q": 2e-6, "ratio": 3e-6}
AMPLITUDE = 1e-3     # strain of the homogeneous check

# sequences: time on level 0, mesh with n = 1 on levels 0-2, the cross
# term with n = 2, 4 on level 1; the homogeneous check's n
TIME_SEQUENCE = (2, 4, 8, 16, 32)
MESH_LEVELS = (0, 1, 2)
CROSS_N = (2, 4)
EXTRA_LEVEL = 3      # long-term elastic force only
CUBE_N = (1, 2, 4, 8, 16, 32, 64, 128, 256)
QUICK = dict(TIME_SEQUENCE=(1, 2, 4, 8), MESH_LEVELS=(0, 1), CROSS_N=(1, 2),
             CUBE_N=(1, 2, 4, 8, 16, 32))


# --------------------------------------------------------------------------
# material split and closed forms
# --------------------------------------------------------------------------
def young_poisson(G, K):
    return 9 * K * G / (3 * K + G), (3 * K - 2 * G) / (2 * (3 * K + G))


def split(E, nu=NU, g=G_REL):
    """The parallel split of the standard linear solid with elastic bulk:
    dict(G0, K0, elastic=(E, nu) of the elastic part (G_a = (1 - g) G0,
    K_a = K0 - K_b), maxwell=(E, nu) of the Maxwell part (G_b = g G0, K_b
    = G_b), A = 1 / (3 G_b tau) of its Norton law)."""
    G0, K0 = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
    Gb = g * G0
    Kb = Gb
    return dict(G0=G0, K0=K0, elastic=young_poisson(G0 - Gb, K0 - Kb),
                maxwell=young_poisson(Gb, Kb), A=1 / (3 * Gb * TAU))


def ramp_response(t, M0, M_inf, T, t_ramp=T_RAMP):
    """Stress per unit final strain of M(t) = M_inf + (M0 - M_inf)
    exp(-t / T) under a strain ramped linearly to 1 over t_ramp and held:
    the convolution of M with the ramp's strain rate."""
    d = M0 - M_inf
    if t <= t_ramp:
        return (M_inf * t + d * T * (1 - math.exp(-t / T))) / t_ramp
    return M_inf + d * T / t_ramp * math.exp(-t / T) * \
        math.expm1(t_ramp / T)


def uniaxial_moduli(G0, K0):
    """Uniaxial stress of the standard linear solid with elastic bulk:
    (E_0, E_inf, T) of the equivalent standard linear solid."""
    return (9 * K0 * G0 / (3 * K0 + G0),
            9 * K0 * G_INF * G0 / (3 * K0 + G_INF * G0),
            TAU * (3 * K0 + G0) / (3 * K0 + G_INF * G0))


def backward_euler_shear(n, G0):
    """The Maxwell branch integrated by backward Euler on the increments of
    the schedule (n per segment): [(time, shear stress per unit strain)]
    for every increment, in order."""
    Ga, Gb = G_INF * G0, G_REL * G0
    out, tb, t0, strain0 = [], 0.0, 0.0, 0.0
    for t1 in TIMES:
        dt = (t1 - t0) / n
        for k in range(n):
            t = t0 + (k + 1) * dt
            strain = min(t / T_RAMP, 1.0)
            tb = (tb + Gb * (strain - strain0)) / (1 + dt / TAU)
            strain0 = strain
            out.append((t, Ga * strain + tb))
        t0 = t1
    return out


# --------------------------------------------------------------------------
# ccx input pieces
# --------------------------------------------------------------------------
def materials(E, scale, creep=True, name="FAT"):
    """*MATERIAL blocks {name}A (elastic part) and {name}B (Maxwell part,
    with Norton creep unless creep is False) for modulus E times scale."""
    s = split(E * scale)
    L = [f"*MATERIAL, NAME={name}A", "*ELASTIC",
         "{!r}, {!r}".format(*s["elastic"]),
         f"*MATERIAL, NAME={name}B", "*ELASTIC",
         "{!r}, {!r}".format(*s["maxwell"])]
    if creep:
        L += ["*CREEP, LAW=NORTON", f"{s['A']!r}, 1.0, 0.0"]
    return L


def schedule(n, boundary, prints):
    """The ramp amplitude and one *VISCO step per segment of TIMES with n
    fixed increments; boundary: lines of the first step (the ramped ones
    with AMPLITUDE=RAMP); prints: the output requests of every step."""
    L = ["*AMPLITUDE, NAME=RAMP, TIME=TOTAL TIME",
         f"0.0, 0.0, {T_RAMP!r}, 1.0, 1.0e4, 1.0"]
    t0 = 0.0
    for t1 in TIMES:
        L += ["*STEP, INC=1000000", f"*VISCO, CETOL={CETOL}, DIRECT",
              f"{(t1 - t0) / n!r}, {t1 - t0!r}"]
        if t0 == 0.0:
            L += boundary
        L += prints + ["*END STEP"]
        t0 = t1
    return L


def series(dat, component, factor):
    """[(time, factor * total force component)] of every 'total force'
    block of a .dat file, in order (ccx prints the time to 7 digits)."""
    times = [float(t) for t in re.findall(
        r"total force \(fx,fy,fz\) for set \S+ and time\s+(\S+)", dat)]
    return [(t, factor * f[component])
            for t, f in zip(times, cp.total_forces(dat))]


def at(values, t):
    """The value of a series at time t (to the printed digits)."""
    return next(v for tt, v in values if abs(tt - t) <= 1e-6 * max(t, 1.0))


# --------------------------------------------------------------------------
# 1. homogeneous check
# --------------------------------------------------------------------------
CUBE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
        (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def cube_input(case, n, amplitude, scale=SCALE):
    """One C3D8 unit cube twice (elastic part, Maxwell part) on the same
    nodes. shear: u_x = amplitude y at every node (all else 0), the force
    is the x reaction of the nodes y = 1; uniaxial: symmetry planes x = 0,
    y = 0, u_z = amplitude z at every node, lateral faces free, the force
    is the z reaction of the nodes z = 1."""
    L = ["*HEADING", f"SLS cube, {case}", "*NODE"]
    L += [f"{i + 1}, {x}, {y}, {z}" for i, (x, y, z) in enumerate(CUBE)]
    L += ["*ELEMENT, TYPE=C3D8, ELSET=PA", "1, 1, 2, 3, 4, 5, 6, 7, 8",
          "*ELEMENT, TYPE=C3D8, ELSET=PB", "2, 1, 2, 3, 4, 5, 6, 7, 8",
          "*NSET, NSET=FACE",
          "3, 4, 7, 8" if case == "shear" else "5, 6, 7, 8"]
    L += materials(E_FAT, scale)
    L += ["*SOLID SECTION, ELSET=PA, MATERIAL=FATA",
          "*SOLID SECTION, ELSET=PB, MATERIAL=FATB"]
    fixed, ramped = ["*BOUNDARY"], ["*BOUNDARY, AMPLITUDE=RAMP"]
    for i, (x, y, z) in enumerate(CUBE):
        if case == "shear":
            fixed.append(f"{i + 1}, 2, 3, 0.0")
            ramped.append(f"{i + 1}, 1, 1, {amplitude * y!r}")
        else:
            if x == 0:
                fixed.append(f"{i + 1}, 1, 1, 0.0")
            if y == 0:
                fixed.append(f"{i + 1}, 2, 2, 0.0")
            ramped.append(f"{i + 1}, 3, 3, {amplitude * z!r}")
    L += schedule(n, fixed + ramped,
                  ["*NODE PRINT, NSET=FACE, TOTALS=ONLY", "RF"])
    return "\n".join(L) + "\n"


def homogeneous_check(workdir, ns, rows):
    """Runs the cube for every n; prints the errors against the closed
    forms, the observed order and the Richardson extrapolation; appends
    rows. Returns the largest relative error of the finest n and of the
    extrapolation."""
    s = split(E_FAT * SCALE)
    G0, K0 = s["G0"], s["K0"]
    exact = {"shear": {t: ramp_response(t, G0, G_INF * G0, TAU)
                       for t in TIMES},
             "uniaxial": {t: ramp_response(t, *uniaxial_moduli(G0, K0))
                          for t in TIMES}}
    summary = {}
    print("\n1. Homogeneous check (C3D8 cube, elastic + Maxwell part on "
          "the same nodes), relative error against the closed form at "
          f"t = {', '.join(f'{t:g}' for t in TIMES)} s:", flush=True)
    for case in ("shear", "uniaxial"):
        component = 0 if case == "shear" else 2
        values = {}
        for n in ns:
            out = cp.run_ccx(workdir, f"cube_{case}_n{n}",
                             cube_input(case, n, AMPLITUDE))
            v = series(out["dat"], component, 1 / AMPLITUDE)
            values[n] = [at(v, t) for t in TIMES]
            errors = [values[n][k] / exact[case][t] - 1
                      for k, t in enumerate(TIMES)]
            extra = ""
            if case == "shear":
                be = backward_euler_shear(n, G0)
                assert len(v) == len(be) and all(
                    abs(a[0] - b[0]) <= 1e-6 * max(b[0], 1) for a, b in
                    zip(v, be)), "increments differ from the schedule"
                dev = max(abs(a[1] / b[1] - 1) for a, b in zip(v, be))
                extra = f"  ccx vs backward Euler {dev:.1e}"
                rows.append(dict(check="homogeneous", case="shear vs "
                                 "backward Euler (max over increments)",
                                 level="", n=n, time_s="", value="",
                                 closed_form="", relative_error=dev))
            print(f"  {case:8s} n = {n:3d}: " +
                  " ".join(f"{e:+.1e}" for e in errors) + extra, flush=True)
            for k, t in enumerate(TIMES):
                rows.append(dict(check="homogeneous", case=case, level="",
                                 n=n, time_s=t, value=values[n][k] / SCALE,
                                 closed_form=exact[case][t] / SCALE,
                                 relative_error=errors[k]))
        n1, n2, n3 = ns[-3:]
        orders = [math.log2(abs((values[n2][k] - values[n1][k]) /
                                (values[n3][k] - values[n2][k])))
                  for k in range(len(TIMES))]
        rich = [2 * values[n3][k] - values[n2][k] for k in range(len(TIMES))]
        rich_errors = [rich[k] / exact[case][t] - 1
                       for k, t in enumerate(TIMES)]
        for k, t in enumerate(TIMES):
            rows.append(dict(check="homogeneous",
                             case=f"{case} Richardson n={n2},{n3}",
                             level="", n="", time_s=t, value=rich[k] / SCALE,
                             closed_form=exact[case][t] / SCALE,
                             relative_error=rich_errors[k]))
        finest = max(abs(values[n3][k] / exact[case][t] - 1)
                     for k, t in enumerate(TIMES))
        print(f"  {case}: observed order (n = {n1}, {n2}, {n3}) "
              f"{min(orders):.3f} to {max(orders):.3f}; largest error at "
              f"n = {n3}: {finest:.1e}; Richardson (n = {n2}, {n3}): "
              + " ".join(f"{e:+.1e}" for e in rich_errors), flush=True)
        summary[case] = (finest, max(abs(e) for e in rich_errors),
                         min(orders), max(orders))
    # pitfall: no creep below a stress of 1e-10 (true MPa, small strain)
    out = cp.run_ccx(workdir, "cube_threshold",
                     cube_input("shear", 8, 1e-5, scale=1.0))
    v = series(out["dat"], 0, 1 / 1e-5)
    be = backward_euler_shear(8, G0 / SCALE)
    dev = at(v, 80.0) / at(be, 80.0) - 1
    rows.append(dict(check="homogeneous", case="unscaled moduli, shear "
                     "1e-5: ccx vs backward Euler at 80 s (creep threshold)",
                     level="", n=8, time_s=80.0, value=at(v, 80.0),
                     closed_form=at(be, 80.0), relative_error=dev))
    print(f"  pitfall: true moduli (E = {E_FAT} MPa) and a shear of 1e-5: "
          f"F(80 s) differs from backward Euler by {dev:+.1e} (no creep "
          "below 1e-10 MPa); hence the moduli times 1e6", flush=True)
    return summary


# --------------------------------------------------------------------------
# 2. the layered punch
# --------------------------------------------------------------------------
def punch_input(level, mode, n=None, indent=cp.INDENT):
    """The punch on calculix_punch's level-`level` mesh, moduli times
    SCALE. mode: 'visco' (the fat as elastic + Maxwell part, *VISCO
    schedule with n increments per segment), 'split' (same split, Maxwell
    part without *CREEP, *STATIC), 'creep_static' (with *CREEP, *STATIC),
    'long_term' (the fat with shear g_inf G0 and K0 only, *STATIC)."""
    r, z = cp.axisymmetric_mesh(level)
    L, sets, _ = cp.layered_axisymmetric_grid(
        r, z, cp.LAYERS, "CAX8R", f"SLS punch, level {level}, {mode}")
    i0 = next(k for k, l in enumerate(L) if l.startswith("*ELEMENT"))
    i1 = next(k for k, l in enumerate(L) if l.startswith("*ELSET"))
    elements = dict((int(l.split(",", 1)[0]), l.split(",", 1)[1])
                    for l in L[i0 + 1:i1])
    elsets, name = {}, None
    for l in L[i1:]:
        if l.startswith("*ELSET"):
            name = l.split("=")[1]
            elsets[name] = []
        else:
            elsets[name] += [int(v) for v in l.split(",")]
    offset = max(elements)
    if mode != "long_term":  # the Maxwell part: same nodes, new numbers
        for name in FAT:
            L.append(f"*ELEMENT, TYPE=CAX8R, ELSET={name}B")
            L += [f"{e + offset},{elements[e]}" for e in elsets[name]]
    for name, nodes in sets.items():
        L.append(f"*NSET, NSET={name}")
        L += cp._lines(nodes)
    for name, _, E in cp.LAYERS:
        if name in FAT:
            assert E == E_FAT
            continue
        L += [f"*MATERIAL, NAME=M{name}", "*ELASTIC",
              f"{E * SCALE!r}, {NU!r}",
              f"*SOLID SECTION, ELSET={name}, MATERIAL=M{name}"]
    if mode == "long_term":
        s = split(E_FAT * SCALE)
        L += ["*MATERIAL, NAME=FATL", "*ELASTIC", "{!r}, {!r}".format(
            *young_poisson(G_INF * s["G0"], s["K0"]))]
        L += [f"*SOLID SECTION, ELSET={name}, MATERIAL=FATL" for name in FAT]
    else:
        L += materials(E_FAT, SCALE, creep=mode != "split")
        L += [f"*SOLID SECTION, ELSET={name}, MATERIAL=FATA" for name in FAT]
        L += [f"*SOLID SECTION, ELSET={name}B, MATERIAL=FATB"
              for name in FAT]
    fixed = ["*BOUNDARY", "BOTTOM, 1, 2, 0.0", "SIDE, 1, 2, 0.0",
             "AXIS, 1, 1, 0.0", "PUNCH, 1, 1, 0.0"]
    prints = ["*NODE PRINT, NSET=PUNCH, TOTALS=ONLY", "RF"]
    if mode == "visco":
        L += schedule(n, fixed + ["*BOUNDARY, AMPLITUDE=RAMP",
                                  f"PUNCH, 2, 2, {-indent!r}"], prints)
    else:
        L += ["*STEP", "*STATIC"] + fixed + \
             [f"PUNCH, 2, 2, {-indent!r}"] + prints + ["*END STEP"]
    return "\n".join(L) + "\n"


def punch_run(level, mode, workdir, n=None):
    """[(time, punch force N)] (ring force 180 RF, axial component,
    divided by SCALE) and ccx's run record."""
    out = cp.run_ccx(workdir, f"punch_{mode}_l{level}" +
                     (f"_n{n}" if n else ""), punch_input(level, mode, n))
    return series(out["dat"], 1, -180 / SCALE), out


def richardson_steps(seq):
    """seq {n: value} for n doubling: (observed orders, first-stage
    extrapolations 2 X_2n - X_n, second stage (4 R_2n - R_n) / 3)."""
    ns = sorted(seq)
    orders = [math.log2(abs((seq[b] - seq[a]) / (seq[c] - seq[b])))
              if seq[c] != seq[b] else float("nan")
              for a, b, c in zip(ns, ns[1:], ns[2:])]
    r1 = [2 * seq[b] - seq[a] for a, b in zip(ns, ns[1:])]
    r2 = [(4 * b - a) / 3 for a, b in zip(r1, r1[1:])]
    return orders, r1, r2


def converge(time_seq, mesh_seq, cross_seq, resolution):
    """One quantity X (Q or the ratio) at one time: time_seq {n: X} on
    level 0, mesh_seq {level: X} with n = 1, cross_seq {n: X(level 1, n) -
    X(level 0, n)} for n = 1 and CROSS_N. Returns (X_ref, uncertainty,
    parts)."""
    orders, r1, r2 = richardson_steps(time_seq)
    x_time = r2[-1]
    u_time = abs(r2[-1] - r1[-1])
    levels = sorted(mesh_seq)
    # the mesh correction from level 0 to the finest level with n = 1,
    # and its change with n (cross term) extrapolated to n -> infinity
    mesh_corr = mesh_seq[levels[-1]] - mesh_seq[levels[0]]
    ns = sorted(cross_seq)
    cross = cross_seq[ns[-1]] - cross_seq[1]
    cross_extra = cross_seq[ns[-1]] - cross_seq[ns[-2]]  # first order
    x_ref = x_time + mesh_corr + cross + cross_extra
    u_mesh = abs(mesh_seq[levels[-1]] - mesh_seq[levels[-2]])
    u_cross = abs(cross_extra)
    u = u_time + u_mesh + u_cross + resolution
    return x_ref, u, dict(orders=orders, r1=r1[-1], r2=r2[-1],
                          u_time=u_time, mesh_corr=mesh_corr,
                          cross=cross + cross_extra, u_mesh=u_mesh,
                          u_cross=u_cross)


def main():
    parser = argparse.ArgumentParser(description="CalculiX reference of "
                                     "the visco-elastic punch relaxation "
                                     "(see the docstring)")
    parser.add_argument("--workdir", default=None)
    parser.add_argument("--quick", action="store_true",
                        help="short sequences, no files written")
    args = parser.parse_args()
    time_seq_n, mesh_levels, cross_n, cube_n = \
        TIME_SEQUENCE, MESH_LEVELS, CROSS_N, CUBE_N
    if args.quick:
        time_seq_n, mesh_levels, cross_n, cube_n = (
            QUICK["TIME_SEQUENCE"], QUICK["MESH_LEVELS"], QUICK["CROSS_N"],
            QUICK["CUBE_N"])
    workdir = args.workdir or tempfile.mkdtemp(prefix="visco_calculix_")
    start = time.perf_counter()
    print(f"ccx: {cp.CCX}; work directory {workdir}")
    s = split(E_FAT)
    print(f"fat: G0 = {s['G0']:.6e}, K0 = {s['K0']:.6e} MPa; elastic part "
          "E, nu = {:.6e}, {:.6f}; Maxwell part E, nu = {:.6e}, {:.6f}, "
          "Norton A = {:.6e} /MPa/s (in ccx: moduli x {:g}, A / {:g})"
          .format(*s["elastic"], *s["maxwell"], s["A"], SCALE, SCALE))
    rows = []
    cube = homogeneous_check(workdir, cube_n, rows)

    # elastic stiffness per level and the overlap check
    print("\n2. Punch. Elastic stiffness (calculix_punch) and the overlap "
          "check (force / (K d) - 1):", flush=True)
    reference = cp.reference_stiffness(NU, workdir, mesh_levels) \
        if len(mesh_levels) >= 3 else None
    K = {}
    for level in mesh_levels:
        if reference is not None:
            K[level] = reference["sequence"][mesh_levels.index(level)]["K"]
        else:
            K[level] = cp.axisymmetric_stiffness(NU, level, workdir)["K"]
    long_term, long_term_force = {}, {}
    for level in mesh_levels[:2]:
        line = f"  level {level}: K = {K[level]:.8f} N/mm"
        modes = ("split", "creep_static", "long_term") if level == 0 \
            else ("split", "long_term")
        for mode in modes:
            f, _ = punch_run(level, mode, workdir)
            q = f[-1][1] / (K[level] * cp.INDENT)
            if mode == "long_term":
                long_term[level] = q
                long_term_force[level] = f[-1][1]
                line += f"; long-term (fat g_inf G0) F / (K d) = {q:.7f}"
            else:
                line += f"; {mode} {q - 1:+.1e}"
            rows.append(dict(check="punch static", case=mode, level=level,
                             n="", time_s="", value=f[-1][1],
                             closed_form=K[level] * cp.INDENT,
                             relative_error=q - 1))
        print(line, flush=True)
    # the relaxed state's mesh convergence beyond the visco levels: the
    # long-term elastic force on the finer levels (level 3: 740k equations,
    # about 45 s, 5.3 GB)
    for level in mesh_levels[2:] + (() if args.quick else (EXTRA_LEVEL,)):
        f, _ = punch_run(level, "long_term", workdir)
        long_term_force[level] = f[-1][1]
        rows.append(dict(check="punch static", case="long_term force N",
                         level=level, n="", time_s="", value=f[-1][1],
                         closed_form="", relative_error=""))
    levels = sorted(long_term_force)
    print("  long-term force by level: " + ", ".join(
        f"{long_term_force[l]:.8f}" for l in levels) + " N; changes " +
        ", ".join(f"{long_term_force[b] / long_term_force[a] - 1:+.1e}"
                  for a, b in zip(levels, levels[1:])), flush=True)
    if reference is not None:
        K_ref, u_K = reference["K"], reference["error_estimate"]
        print(f"  reference K = {K_ref:.8f} N/mm +- {u_K:.1e} "
              f"({u_K / K_ref:.1e} relative)", flush=True)
    else:
        K_ref, u_K = K[mesh_levels[-1]], abs(K[mesh_levels[-1]] - K[0])

    # visco-elastic runs
    runs = {}

    def visco(level, n):
        if (level, n) not in runs:
            f, out = punch_run(level, "visco", workdir, n)
            runs[level, n] = f
            print(f"  visco level {level} n = {n:2d}: {out['equations']} "
                  f"equations, {7 * n} increments, {out['time_s']:6.1f} s; "
                  f"F(0.1) = {at(f, T_RAMP):.8f} N, "
                  f"F(80) = {at(f, 80.0):.8f} N",
                  flush=True)
            for t in TIMES:
                rows.append(dict(check="punch visco", case="force N",
                                 level=level, n=n, time_s=t,
                                 value=at(f, t), closed_form="",
                                 relative_error=""))
        return runs[level, n]

    print("\n  Visco-elastic runs (n increments per segment):", flush=True)
    for n in time_seq_n:
        visco(mesh_levels[0], n)
    for level in mesh_levels:
        visco(level, 1)
    for n in cross_n:
        visco(mesh_levels[1], n)

    def Q(level, n, t):
        return at(visco(level, n), t) / (K[level] * cp.INDENT)

    def ratio(level, n, t):
        return Q(level, n, t) / Q(level, n, T_RAMP)

    l0, l1 = mesh_levels[0], mesh_levels[1]
    results = []
    print("\n  Convergence (per time; time: observed orders on level 0, "
          "second Richardson correction; mesh: level 0 -> finest with n = "
          "1, its change with n):")
    for t in TIMES:
        entry = dict(time_s=t)
        for name, fn in (("Q", Q), ("ratio", ratio)):
            x_ref, u, parts = converge(
                {n: fn(l0, n, t) for n in time_seq_n},
                {level: fn(level, 1, t) for level in mesh_levels},
                {n: fn(l1, n, t) - fn(l0, n, t)
                 for n in (1,) + tuple(cross_n)},
                RESOLUTION[name] * abs(fn(l0, time_seq_n[-1], t)))
            entry[name], entry["u_" + name] = x_ref, u
            if name == "ratio" and t == T_RAMP:
                continue
            print(f"  t = {t:5g} {name:5s}: {x_ref:.8f} +- {u:.1e}; orders "
                  + ", ".join(f"{o:.2f}" for o in parts["orders"]) +
                  f"; R1 {parts['r1']:.8f}, R2 {parts['r2']:.8f} (time "
                  f"+- {parts['u_time']:.1e}); mesh {parts['mesh_corr']:+.1e}"
                  f" +- {parts['u_mesh']:.1e}, cross {parts['cross']:+.1e} "
                  f"+- {parts['u_cross']:.1e}", flush=True)
        entry["ratio"], entry["u_ratio"] = (1.0, 0.0) if t == T_RAMP else \
            (entry["ratio"], entry["u_ratio"])
        entry["force"] = entry["Q"] * K_ref * cp.INDENT
        entry["u_force"] = entry["force"] * (entry["u_Q"] / entry["Q"] +
                                             u_K / K_ref)
        results.append(entry)

    print(f"\n  Reference (d = {cp.INDENT} mm over {T_RAMP} s, held; K_ref "
          f"= {K_ref:.8f} N/mm):")
    print(f"  {'t s':>6s} {'F N':>12s} {'+-':>8s} {'F/F(0.1)':>11s} "
          f"{'+-':>8s} {'F/(K d)':>11s}")
    for e in results:
        print(f"  {e['time_s']:6g} {e['force']:12.8f} {e['u_force']:8.1e} "
              f"{e['ratio']:11.8f} {e['u_ratio']:8.1e} {e['Q']:11.8f}")
    q0 = results[0]["Q"]
    print(f"  long-term limit (elastic, fat shear g_inf G0): F / F(0.1) = "
          f"{long_term[l0] / q0:.6f} (level {l0}), "
          f"{long_term[mesh_levels[1]] / q0:.6f} (level {mesh_levels[1]})")
    print(f"  consistency: Q(t) / Q(0.1) - ratio: " + ", ".join(
        f"{e['Q'] / q0 - e['ratio']:+.1e}" for e in results))
    elapsed = time.perf_counter() - start
    print(f"\nhomogeneous: largest error at the finest n "
          f"{max(c[0] for c in cube.values()):.1e}, Richardson "
          f"{max(c[1] for c in cube.values()):.1e}; total run time "
          f"{elapsed:.0f} s")
    if args.quick:
        return
    os.makedirs(os.path.dirname(RESULTS), exist_ok=True)
    with open(RESULTS, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time_s", "force_N", "force_ratio", "uncertainty_force",
                    "uncertainty_ratio"])
        for e in results:
            w.writerow([e["time_s"], f"{e['force']:.9g}",
                        f"{e['ratio']:.9g}", f"{e['u_force']:.2g}",
                        f"{e['u_ratio']:.2g}"])
    with open(CHECKS, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["check", "case", "level", "n",
                                          "time_s", "value", "closed_form",
                                          "relative_error"])
        w.writeheader()
        for row in rows:
            w.writerow({k: (f"{v:.9g}" if isinstance(v, float) else v)
                        for k, v in row.items()})
    print(f"wrote {RESULTS} and {CHECKS}")


if __name__ == "__main__":
    main()
