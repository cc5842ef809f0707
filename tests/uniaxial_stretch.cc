// Homogeneous uniaxial stretch and compression of a neo-Hookean and of a
// corotational block
// (2 x 2 x 2 mm, symmetry rollers on x = -1, y = -1 and the bottom, the
// face x = 1 moved to stretch lambda, the other faces free) through Newton's
// method with load steps, against the closed-form solution of this material
// law: the lateral stretch t solves sigma_yy = 0, i.e.
//   neo-Hookean:  mu J^{-2/3} (t^2 - (lambda^2 + 2 t^2) / 3) + J U'(J) = 0,
//   corotational: mu (2 a t^2 - 2/3 a s - 2 b t + 2/3 b (lambda + 2 t))
//                 + J U'(J) = 0,  a = J^{-2/3}, b = J^{-1/3},
//                 s = lambda^2 + 2 t^2 (F = U = diag(lambda, t, t), R = I),
// J = lambda t^2, U'(J) = kappa/2
// (J - 1/J), and the force is P_xx A_0 = tau_xx / lambda * A_0. The deformation
// is homogeneous, so the finite elements reproduce it exactly (displacement and
// mixed formulations). The Newton residuals of the last load step of one case
// show the quadratic convergence (with the default inexact Newton method):
// the order estimated from the last three is at least 1.8.

#include <deal.II/base/function.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/mesh/background_mesh.h>
#include <ssc/nonlinear/elastic_problem.h>
#include <ssc/nonlinear/load_stepping.h>
#include <ssc/nonlinear/newton_solver.h>

#include "block_stretch.h"
#include "quiet_elasticity.h"
#include "tests.h"

using namespace dealii;

/// Force on the face x = 1 (area 4 mm^2) for stretch lambda of a block of
/// Young's modulus E and Poisson's ratio nu.
double
closed_form_force(const std::string &model,
                  const double       E,
                  const double       nu,
                  const double       lambda)
{
  const double mu = E / (2 * (1 + nu)), kappa = E / (3 * (1 - 2 * nu));
  const auto   stress_yy = [&](const double t, double &tau_xx) {
    const double J          = lambda * t * t;
    const double J_pressure = J * 0.5 * kappa * (J - 1 / J);
    double       shear_xx, shear_yy;
    if (model == std::string("neo-Hookean"))
      {
        const double scale = mu * std::pow(J, -2. / 3.);
        shear_xx =
          scale * (lambda * lambda - (lambda * lambda + 2 * t * t) / 3);
        shear_yy = scale * (t * t - (lambda * lambda + 2 * t * t) / 3);
      }
    else
      {
        // tau = P F^T of mu |J^{-1/3} U - I|^2 with U = F
        const double a = std::pow(J, -2. / 3.), b = std::pow(J, -1. / 3.);
        const double s = lambda * lambda + 2 * t * t, T = lambda + 2 * t;
        shear_xx = mu * (2 * a * lambda * lambda - 2. / 3 * a * s -
                         2 * b * lambda + 2. / 3 * b * T);
        shear_yy =
          mu * (2 * a * t * t - 2. / 3 * a * s - 2 * b * t + 2. / 3 * b * T);
      }
    tau_xx = shear_xx + J_pressure;
    return shear_yy + J_pressure;
  };
  // bisection for the lateral stretch
  double lo = 0.3, hi = 2., tau_xx = 0;
  for (unsigned int k = 0; k < 200; ++k)
    {
      const double mid                       = 0.5 * (lo + hi);
      (stress_yy(mid, tau_xx) > 0 ? hi : lo) = mid;
    }
  stress_yy(0.5 * (lo + hi), tau_xx);
  return tau_xx / lambda * 4.;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::LayerStack layers;
  layers.add_layer("block", ssc::LayerKind::deep, "2", 0.01, 0.45, 2);
  const ssc::MeshParameters mesh_parameters = uniform_patch(2, 1);
  ssc::BackgroundMesh       mesh(layers, mesh_parameters, MPI_COMM_WORLD);
  mesh.build();
  for (const auto model :
       {std::string("neo-Hookean"), std::string("corotational")})
    for (const auto formulation :
         {ssc::Formulation::displacement, ssc::Formulation::mixed})
      for (const double lambda : {1.5, 0.7})
        {
          layers.set_model(0, model);
          ssc::ElasticityParameters parameters;
          parameters.formulation             = formulation;
          parameters.linear_solver.tolerance = 1e-12;
          ssc::NewtonParameters newton_parameters;
          newton_parameters.relative_tolerance = 1e-12;
          newton_parameters.absolute_tolerance = 1e-16;
          QuietElasticity     quiet(mesh, layers, parameters);
          ssc::ElasticSystem &elasticity = quiet.elasticity;
          elasticity.field().distribute_dofs();
          const auto report = stretch_block(
            elasticity, newton_parameters, quiet.pcout, lambda, false, 0.1);
          const double force    = elasticity.reaction(1)[0];
          const double expected = closed_form_force(model, 0.01, 0.45, lambda);
          std::ostringstream line;
          line << model << ", " << ssc::to_string(formulation) << ", stretch "
               << lambda << ": force " << std::setprecision(6) << force
               << " N, closed form " << expected
               << " N, relative difference below 1e-8: "
               << (std::abs(force / expected - 1) < 1e-8 ? "yes" : "no");
          deallog << line.str() << std::endl;
          if (formulation == ssc::Formulation::mixed && lambda == 1.5)
            {
              std::ostringstream residuals;
              residuals << "  Newton residuals of the last increment:";
              for (const double r : report.last_residuals)
                residuals << ' ' << std::scientific << std::setprecision(1)
                          << r;
              deallog << residuals.str() << std::endl;
              // the order of convergence from the last three residuals
              // above round-off: log(r3/r2) / log(r2/r1), 2 if quadratic
              std::vector<double> above;
              for (const double r : report.last_residuals)
                if (r > 1e-15)
                  above.push_back(r);
              const unsigned int k     = above.size();
              const double       order = k < 3 ?
                                           0. :
                                           std::log(above[k - 1] / above[k - 2]) /
                                       std::log(above[k - 2] / above[k - 3]);
              deallog << "  order of convergence at least 1.8 (quadratic): "
                      << (order >= 1.8 ? "yes" : "no") << std::endl;
            }
        }
}
