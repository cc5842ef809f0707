// The stresses ssc writes, against closed forms: under a homogeneous
// deformation F = diag(1.2, 0.9, 1.1), prescribed on the whole boundary of
// a block and solved by Newton's method, every cell's Cauchy stress (what
// write_volume_vtu() writes) equals the principal stresses
// sigma_i = (lambda_i / J) dW/dlambda_i of each law's energy in the
// principal stretches, derived by hand here (linear, corotational,
// neo-Hookean, and neo-Hookean with a growth of 0.3); the septa's membrane
// von Mises stress (F S F^T / J_s of the St Venant-Kirchhoff membrane in the
// plane z = const) and the ligaments' axial force (E A e |F tau| along x)
// that the microstructure output writes equal theirs.

#include <deal.II/base/function.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include <ssc/materials/cable_law.h>
#include <ssc/materials/membrane_law.h>
#include <ssc/mechanics/elastic_system.h>
#include <ssc/mesh/background_mesh.h>
#include <ssc/nonlinear/elastic_problem.h>
#include <ssc/nonlinear/load_stepping.h>
#include <ssc/nonlinear/newton_solver.h>
#include <ssc/output/volume_output.h>

#include "quiet_elasticity.h"
#include "tests.h"

using namespace dealii;

namespace
{
  const double E = 0.02, nu = 0.45;
  const double stretch[3] = {1.2, 0.9, 1.1};

  /// u = (F - I) X for the diagonal F of the stretches.
  class HomogeneousDisplacement : public Function<3>
  {
  public:
    HomogeneousDisplacement()
      : Function<3>(3)
    {}

    double
    value(const Point<3> &p, const unsigned int component) const override
    {
      return (stretch[component] - 1.) * p[component];
    }
  };

  /// Principal Cauchy stress i of @p model, by hand.
  double
  closed_form(const std::string &model,
              const unsigned int i,
              const double       gamma)
  {
    const double mu = E / (2 * (1 + nu)), kappa = E / (3 * (1 - 2 * nu));
    const double J = stretch[0] * stretch[1] * stretch[2];
    if (model == std::string("linear"))
      {
        const double trace = stretch[0] + stretch[1] + stretch[2] - 3.;
        return 2 * mu * (stretch[i] - 1. - trace / 3.) + kappa * trace;
      }
    // U'(J) of U = kappa/4 (J^2 - 1 - 2 ln J), at J / gamma
    const double pressure = 0.5 * kappa * (J / gamma - gamma / J);
    double       dW       = 0; // d W_iso / d lambda_i
    if (model == std::string("neo-Hookean"))
      {
        // W_iso = mu/2 (J^{-2/3} sum lambda_k^2 - 3)
        double sum = 0;
        for (const double l : stretch)
          sum += l * l;
        dW = mu * std::pow(J, -2. / 3.) * (stretch[i] - sum / (3 * stretch[i]));
      }
    else
      // W_iso = mu sum (J^{-1/3} lambda_k - 1)^2
      for (unsigned int k = 0; k < 3; ++k)
        dW += 2 * mu * (std::pow(J, -1. / 3.) * stretch[k] - 1.) *
              std::pow(J, -1. / 3.) *
              ((i == k ? 1. : 0.) - stretch[k] / (3 * stretch[i]));
    return gamma * stretch[i] / J * dW + pressure;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const auto &[model, growth] :
       std::vector<std::pair<std::string, double>>{
         {std::string("linear"), 0.},
         {std::string("corotational"), 0.},
         {std::string("neo-Hookean"), 0.},
         {std::string("neo-Hookean"), 0.3}})
    {
      ssc::LayerStack layers;
      layers.add_layer("block", ssc::LayerKind::deep, "2", E, nu, 2);
      layers.set_model(0, model);
      ssc::BackgroundMesh mesh(layers, uniform_patch(2, 1), MPI_COMM_WORLD);
      mesh.build();
      ssc::ElasticityParameters parameters;
      parameters.formulation = ssc::Formulation::mixed;
      QuietElasticity     quiet(mesh, layers, parameters);
      ssc::ElasticSystem &system = quiet.elasticity;
      system.field().distribute_dofs();
      std::vector<ssc::DirichletCondition> conditions;
      const auto values = std::make_shared<HomogeneousDisplacement>();
      for (types::boundary_id id = 0; id < 6; ++id)
        conditions.push_back({id, ComponentMask(3, true), values, {}});
      system.setup(conditions);
      if (growth > 0)
        system.growth().sample(system.field(),
                               [growth](const Point<3> &, const unsigned int) {
                                 return growth;
                               });
      if (model == std::string("linear"))
        solve_linear(system);
      else
        {
          ssc::NewtonParameters newton;
          newton.relative_tolerance = 1e-12;
          ssc::ElasticProblem problem(system);
          ssc::NewtonSolver   solver(problem, newton, quiet.pcout, false);
          ssc::LoadStepper    stepper(solver);
          double              increment = 0.25;
          stepper.follow(
            0.,
            1.,
            increment,
            [&system](const double load) {
              system.constraints().set_dirichlet_scale(load);
            },
            ssc::LoadDependence::right_hand_side);
        }
      const auto stresses      = ssc::cell_cauchy_stresses(system.field(),
                                                      system.materials(),
                                                      system.growth(),
                                                      system.history());
      double     largest_error = 0, scale = 0;
      for (const auto &cell : mesh.triangulation().active_cell_iterators())
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            {
              const double exact =
                i == j ? closed_form(model, i, 1. + growth) : 0.;
              largest_error =
                std::max(largest_error,
                         std::abs(stresses[cell->active_cell_index()][i][j] -
                                  exact));
              scale = std::max(scale, std::abs(exact));
            }
      std::ostringstream line;
      line << model << ", growth " << growth
           << ": sigma_xx = " << std::setprecision(6)
           << 1e3 * closed_form(model, 0, 1. + growth)
           << " kPa; written cell stresses equal the closed form to 1e-8: "
           << (largest_error < 1e-8 * scale ? "yes" : "no");
      deallog << line.str() << std::endl;
    }

  // the septa and ligament measures of the microstructure output
  Tensor<2, 3> F;
  for (unsigned int i = 0; i < 3; ++i)
    F[i][i] = stretch[i];
  const double           Em = 0.1, num = 0.3, t = 0.1, A = 0.07;
  const ssc::MembraneLaw membrane(ssc::IsotropicModuli(Em, num), t, false);
  const double           lambda_ps = Em * num / (1 - num * num);
  const double           two_mu    = Em / (1 + num);
  const double           Ex        = 0.5 * (stretch[0] * stretch[0] - 1);
  const double           Ey        = 0.5 * (stretch[1] * stretch[1] - 1);
  const double           Sx        = lambda_ps * (Ex + Ey) + two_mu * Ex;
  const double           Sy        = lambda_ps * (Ex + Ey) + two_mu * Ey;
  const double           sx        = stretch[0] * Sx / stretch[1];
  const double           sy        = stretch[1] * Sy / stretch[0];
  const double           mises     = std::sqrt(sx * sx - sx * sy + sy * sy);
  const double           written =
    membrane.von_mises_stress(F,
                              Tensor<1, 3>({0., 0., 1.}),
                              ssc::Kinematics::finite_strain);
  deallog << "membrane in z = const: von Mises " << std::setprecision(6)
          << 1e3 * mises << " kPa, written equals it to 1e-12: "
          << (std::abs(written - mises) < 1e-12 * mises ? "yes" : "no")
          << std::endl;
  const ssc::CableLaw cable(Em, A, true);
  const double        force = Em * A * Ex * stretch[0];
  deallog << "cable along x: axial force " << 1e3 * force
          << " mN, written equals it to 1e-12: "
          << (std::abs(cable.current_force(F,
                                           Tensor<1, 3>({1., 0., 0.}),
                                           ssc::Kinematics::finite_strain) -
                       force) < 1e-12 * force ?
                "yes" :
                "no")
          << "; compressed along y it is slack: "
          << (cable.current_force(F,
                                  Tensor<1, 3>({0., 1., 0.}),
                                  ssc::Kinematics::finite_strain) == 0. ?
                "yes" :
                "no")
          << std::endl;
}
