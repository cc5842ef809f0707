#include <ssc/mechanics/linear_solver_parameters.h>

namespace ssc
{
  void
  LinearSolverParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.add_parameter(
      "Method",
      method,
      "cg: CG on the displacement system with the Preconditioner below "
      "(every formulation; the pressure condensed, so its iterations grow "
      "with the bulk modulus). block: the displacement-pressure saddle "
      "point of the mixed formulations (mixed, mean dilatation, enhanced) "
      "by FGMRES with a block-triangular preconditioner, the Preconditioner "
      "below on the displacement block, which keeps a bulk modulus of at "
      "most 8 mu whatever nu, and the cells' pressure blocks for the Schur "
      "complement: the same displacement, with iterations that grow far "
      "less with nu than CG's (layered punch, Q1 with amg: 83 / 171 / 309 "
      "against 70 / 208 / 1444 at nu = 0.3 / 0.49 / 0.4999; with gmg and "
      "Q2-P1, Degree = 2 and Formulation = mixed, 27 at nu 0.4999 on 77k "
      "and 583k DoFs, about 40 with a layer 1000 times stiffer; Q1-P0 is "
      "not inf-sup stable and its iterations double with each refinement "
      "at nu 0.4999; "
      "benchmarks/multigrid_layered). "
      "direct: sparse LU factorisation (MUMPS through Trilinos Amesos) of "
      "the displacement system: exact whatever nu and contrast, its memory "
      "and time grow faster than linearly with the DoFs (small and "
      "medium problems). Trust-region steps always use CG, with the "
      "Preconditioner below.");
    prm.add_parameter(
      "Preconditioner",
      preconditioner,
      "amg: Trilinos ML smoothed-aggregation AMG with the rigid-body modes, "
      "rebuilt for every matrix; its Krylov iterations grow with nu, the "
      "layer contrast and the degree. cholesky: the sparse Cholesky factor "
      "(CHOLMOD, supernodal, fill-reducing ordering) of a recent matrix, "
      "kept across Newton iterations and load steps while the Krylov "
      "solver needs at most Refactorization iterations with it, "
      "refactorised otherwise: robust in nu, contrast and degree, its "
      "memory and factorisation time grow faster than linearly with the "
      "DoFs; one MPI rank only. A tangent that is not positive definite "
      "(a Newton iterate past equilibrium or a stability limit) is "
      "factorised as L D L^T instead (MUMPS, symmetric indefinite with "
      "pivoting) and solved by GMRES (Factor indefinite tangents); "
      "trust-region steps, which need a positive definite preconditioner, "
      "use amg for it. ldlt: as cholesky, but every tangent is factorised "
      "as L D L^T by MUMPS distributed over all MPI ranks (its inertia "
      "tells whether the tangent is positive definite): the same answers "
      "on any number of ranks, each rank holding part of the factor; on a "
      "2-core machine no faster than cholesky on one rank "
      "(benchmarks/distributed_factor). gmg: a geometric multigrid V-cycle "
      "on the mesh's refinement levels (Mesh/Global refinements >= 1, no "
      "local refinement), Galerkin level matrices of the tangent (septa, "
      "ligaments and contact included), Chebyshev smoothing on the "
      "vertical line blocks (robust to the thin layers' flat cells) and a "
      "direct solve on the coarse mesh: CG iterations nearly independent "
      "of the refinement, memory and time linear in the DoFs, on any "
      "number of MPI ranks with the same iterations; for nearly "
      "incompressible layers (nu near 0.5) use it with Method = block and "
      "Q2-P1 (benchmarks/multigrid_layered). A tangent whose line blocks "
      "are not "
      "positive definite gets amg.");
    prm.add_parameter(
      "Factor indefinite tangents",
      factor_indefinite,
      "With Preconditioner = cholesky or ldlt: factorise a tangent that is "
      "not positive definite as L D L^T (true), or precondition it with amg "
      "(false: for comparison, GMRES then needs thousands of iterations).");
    prm.add_parameter(
      "Refactorization iterations",
      refactorization_iterations,
      "With Preconditioner = cholesky or ldlt (or gmg with Keep V-cycle): "
      "a solve preconditioned by the factor (V-cycle) of an earlier matrix "
      "stops after this many iterations, the current matrix is factorised "
      "(its V-cycle built) and the solve continues with the new one.",
      Patterns::Integer(1, 10000));
    prm.add_parameter(
      "Keep V-cycle",
      keep_vcycle,
      "With Preconditioner = gmg: keep the V-cycle of an earlier tangent "
      "(its Galerkin levels, line blocks, Chebyshev bounds and coarse "
      "factor; the finest level's product is always the current "
      "tangent's) across Newton iterations and load steps, as the factors "
      "are kept: a solve that needs more than Refactorization iterations "
      "with it rebuilds the V-cycle for the current tangent and goes on. "
      "Saves the V-cycle's setup (about a third of the solve time on the "
      "forearm scene) at the cost of more CG iterations. Off by default: "
      "on the forearm scene on 2 ranks it took another path in each "
      "repetition, for a reason not yet found, and saved 6 % at best "
      "(benchmarks/forearm/README.md, \"Keeping the V-cycle\"). "
      "Trust-region steps rebuild it for every new tangent.");
    prm.add_parameter("Tolerance",
                      tolerance,
                      "CG stops when the residual has dropped by this factor "
                      "relative to the right-hand side. At most 1e-3: a "
                      "looser one stops CG before its iterate is an answer "
                      "(at 1 it stops before the first iteration).",
                      Patterns::Double(1e-16, 1e-3));
    prm.add_parameter("Max iterations",
                      max_iterations,
                      "CG iteration limit. Reaching it is an error, but "
                      "for a Newton update whose residual is already below "
                      "Nonlinear solver/Acceptable forcing term times the "
                      "right-hand side or Newton's own tolerance: that "
                      "update is kept as an inexact step.",
                      Patterns::Integer(1, 100000));
    prm.add_parameter("Rigid body modes",
                      rigid_body_modes,
                      "Give the AMG preconditioner the six rigid-body modes "
                      "as near-null space (true) or only the three "
                      "translations (false, for comparison).");
    prm.add_parameter("Smoothed aggregation",
                      smoothed_aggregation,
                      "Smooth the AMG prolongator (true: fewest CG "
                      "iterations) or use plain aggregation (false: about "
                      "35 % less memory, about 1.7 times the iterations).");
    prm.add_parameter("Aggregation threshold",
                      aggregation_threshold,
                      "ML smoothed-aggregation drop tolerance.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Smoother sweeps",
                      smoother_sweeps,
                      "Chebyshev smoother sweeps per AMG level.",
                      Patterns::Integer(1, 10));
    prm.leave_subsection();
  }
} // namespace ssc
