// Punch/Depth error estimate = enriched degree: the run's own estimate of
// the discretisation error of the depth at each force, one Newton step of
// Q2-P0 on the same mesh from the converged Q1 state. On the coarse forearm
// indentation (linear layers, lobules, septa and ligaments, a locally
// refined ring with hanging nodes): for a linear problem one Newton step
// is the exact solve, so the Q1 depth plus the estimate must be the depth
// of a Q2-P0 run of the same scene (1e-6), which checks the interpolation
// of the state, the ties, the hanging nodes and the force on the richer
// system; the estimate changes with the mesh (one more refinement of the
// ring, a smaller estimate). At finite strain with the edge contact it is
// positive (Q1 is the stiffer discretisation) and smaller than the depth
// at 0.1 N; at 0.35 N the Q2-P0 tangent at the Q1 state is indefinite, and
// the run goes on without an estimate there (NaN) instead of reporting a
// step along negative curvature. The same on 2 ranks (the paired cells of
// the two meshes, the richer system distributed); the Q2 steps are solved
// with a factor, CHOLMOD's on one rank and MUMPS's distributed L D L^T on
// more.

#include <cmath>
#include <iomanip>
#include <string>

#include "indentation_run.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string factor =
    std::string("Elasticity/Linear solver/Preconditioner=") +
    (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1 ? "cholesky" :
                                                                    "ldlt");
  const std::vector<std::string> linear = {"Punch/Forces=0.35, 1.0", factor};
  const std::string estimate = "Punch/Depth error estimate=enriched degree";

  const auto q1               = run_indentation("indentation_small.prm",
                                  linear,
                                  {"Run/Name=q1_estimate", estimate});
  const auto q2               = run_indentation("indentation_small.prm",
                                  linear,
                                  {"Run/Name=q2_reference",
                                                 "Elasticity/Degree=2",
                                                 "Elasticity/Formulation=mean dilatation"});
  double     largest_mismatch = 0;
  for (unsigned int k = 0; k < q1.depths.size(); ++k)
    {
      const double estimated = q1.depths[k] + q1.depth_error_estimates[k];
      largest_mismatch =
        std::max(largest_mismatch,
                 std::abs(estimated - q2.depths[k]) / q2.depths[k]);
      dealii::deallog << std::setprecision(5) << "linear, " << q1.forces[k]
                      << " N: Q1 " << q1.depths[k] << " mm, estimated error "
                      << std::showpos << q1.depth_error_estimates[k]
                      << std::noshowpos << " mm, Q2-P0 " << q2.depths[k]
                      << " mm" << std::endl;
    }
  dealii::deallog << "linear: Q1 depth + estimate = Q2-P0 depth (1e-6): "
                  << (largest_mismatch < 1e-6 ? "yes" : "no") << std::endl;

  const auto finer =
    run_indentation("indentation_small.prm",
                    linear,
                    {"Run/Name=q1_estimate_finer",
                     estimate,
                     "Mesh/Region of interest/Local refinements=2"});
  dealii::deallog << "linear, one more refinement of the ring: estimated "
                     "error "
                  << std::showpos << std::setprecision(5)
                  << finer.depth_error_estimates.back() << std::noshowpos
                  << " mm at " << finer.forces.back()
                  << " N, smaller than on the coarser ring: "
                  << (std::abs(finer.depth_error_estimates.back()) <
                          std::abs(q1.depth_error_estimates.back()) ?
                        "yes" :
                        "no")
                  << std::endl;

  const auto   finite = run_indentation("indentation_neo_hookean.prm",
                                      {"Punch/Contact=frictionless",
                                         "Punch/Edge contact=true",
                                         factor},
                                      {"Run/Name=finite_estimate",
                                         "Punch/Control=force",
                                         "Punch/Forces=0.1, 0.35",
                                         estimate});
  const double change = finite.depth_error_estimates.front();
  dealii::deallog << "finite strain with edge contact, 0.1 N: depth "
                  << std::setprecision(4) << finite.depths.front()
                  << " mm, estimated error " << std::showpos << change
                  << std::noshowpos << " mm; positive and below the depth: "
                  << (change > 0 && change < finite.depths.front() ? "yes" :
                                                                     "no")
                  << std::endl;
  dealii::deallog << "finite strain, 0.35 N: depth " << finite.depths.back()
                  << " mm, no estimate (indefinite Q2-P0 tangent): "
                  << (std::isnan(finite.depth_error_estimates.back()) ? "yes" :
                                                                        "no")
                  << std::endl;
}
