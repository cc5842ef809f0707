// Creep of the visco-elastic law (a neo-Hookean layer with one deviatoric
// Prony term, ViscoelasticMaterial) under a load applied at t = 0 and held,
// against the closed form of the same law in the small-strain limit (where
// the law is the standard linear solid in shear with an elastic bulk):
//   shear creep compliance J(t) = 1/mu_inf - (1/mu_inf - 1/mu) e^{-t/tau_c},
//   mu_inf = g_inf mu, retardation time tau_c = tau / g_inf.
// 1. Uniaxial stress, through the whole mechanics as the creep scene applies
//    its force: a 2 x 2 x 2 mm block of 8 cells on rollers (x = -1, y = -1,
//    z = -2), its face x = 1 tied to one master dof carrying the force
//    (force control, TiedCondition). Nominal stress sigma = 3e-10 MPa
//    (strain about 3e-8..5e-8: the law's nonlinearity, of the order of the
//    strain, and the round-off of C - I, 1e-16 / strain, are both far
//    below the checked 1e-6):
//    eps_xx(t) = sigma (J(t) / 3 + 1 / (9 kappa)).
// 2. Simple shear at a material point, F = I + gamma e_x e_y (J = 1, no
//    pressure): the nominal shear stress P_xy = 1e-6 MPa held, gamma solved
//    by Newton's method with the law's tangent in every step:
//    gamma(t) = P_xy J(t) (nonlinearity of order gamma^2 = 1e-8).
// Both at dt = 0.1, 0.05, 0.025, 0.0125 s: the relative error at four times,
// the observed order of the time integration (from the coarser steps) and
// whether the finest step is within 1e-6.

#include <deal.II/base/function.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

#include <ssc/materials/layer_materials.h>
#include <ssc/materials/viscoelastic_material.h>
#include <ssc/nonlinear/elastic_problem.h>
#include <ssc/nonlinear/newton_solver.h>

#include "quiet_elasticity.h"
#include "tests.h"

using namespace dealii;

namespace
{
  constexpr double E     = 0.01;
  constexpr double nu    = 0.45;
  constexpr double t_end = 10.;

  const ssc::PronySeries prony{{0.4}, {2.}};

  /// The closed form's shear creep compliance J(t), 1/MPa.
  double
  creep_compliance(const double t, const double mu)
  {
    const double mu_inf = prony.long_term_fraction() * mu;
    const double tau_c = prony.relaxation_times[0] / prony.long_term_fraction();
    return 1. / mu_inf - (1. / mu_inf - 1. / mu) * std::exp(-t / tau_c);
  }

  ssc::LayerStack
  block_layers()
  {
    ssc::LayerStack layers;
    layers.add_layer("block", ssc::LayerKind::SAT, "2", E, nu, 2);
    layers.set_model(0, "neo-Hookean");
    layers.set_viscoelasticity(0,
                               prony.relative_moduli,
                               prony.relaxation_times);
    return layers;
  }

  /// The block's axial strain at t = 0, dt, 2 dt, ..., t_end under the
  /// nominal stress @p sigma applied at t = 0 and held; @p measure(t, eps)
  /// after each step.
  template <typename Measure>
  void
  uniaxial_block_creep(const double sigma, const double dt, Measure measure)
  {
    using namespace ssc::BoundaryId;
    const ssc::LayerStack layers = block_layers();
    ssc::BackgroundMesh   mesh(layers, uniform_patch(2, 1), MPI_COMM_WORLD);
    mesh.build();
    ssc::ElasticityParameters parameters;
    parameters.formulation             = ssc::Formulation::displacement;
    parameters.linear_solver.tolerance = 1e-13;
    ssc::NewtonParameters newton_parameters;
    // the round-off of the residual at strains of 3e-8 is a few 1e-8 of
    // the load; one Newton step reaches it
    newton_parameters.relative_tolerance = 1e-7;
    newton_parameters.absolute_tolerance = 1e-22;
    QuietElasticity     quiet(mesh, layers, parameters);
    ssc::ElasticSystem &elasticity = quiet.elasticity;
    elasticity.field().distribute_dofs();
    const auto zero      = std::make_shared<Functions::ZeroFunction<3>>(3);
    const auto component = [](const unsigned int c) {
      ComponentMask mask(3, false);
      mask.set(c, true);
      return mask;
    };
    elasticity.setup({{x_min, component(0), zero, {}},
                      {y_min, component(1), zero, {}},
                      {bottom, component(2), zero, {}}},
                     {{x_max, 0, {}, Point<3>(1, 0, -1)}});
    ssc::ElasticProblem problem(elasticity);
    ssc::NewtonSolver   newton(problem, newton_parameters, quiet.pcout, false);
    const types::global_dof_index master =
      elasticity.constraints().master_dof(0);
    const double area = 4., length = 2.;

    const unsigned int n_steps = std::lround(t_end / dt);
    for (unsigned int n = 0; n <= n_steps; ++n)
      {
        const double t = n * dt;
        elasticity.constraints().apply(elasticity.field());
        elasticity.loads().nodal_forces = {{master, sigma * area}};
        // t = 0: the load arrives in no time, the instantaneous response
        elasticity.set_time(t);
        const ssc::NewtonReport report = newton.solve();
        AssertThrow(report.converged, ExcMessage(report.failure));
        AssertThrow(problem.accept_state(), ExcInternalError());
        measure(t, elasticity.field().solution()[master] / length);
      }
  }

  /// The shear strain of a material point at t = 0, dt, ..., t_end under
  /// the nominal shear stress @p P held from t = 0.
  template <typename Measure>
  void
  simple_shear_creep(const ssc::Material &law,
                     const double         P,
                     const double         dt,
                     Measure              measure)
  {
    const unsigned int  n = law.n_history_variables();
    std::vector<double> committed(n), trial(n);
    const Point<3>      X;
    double              gamma = 0;

    const unsigned int n_steps = std::lround(t_end / dt);
    for (unsigned int step = 0; step <= n_steps; ++step)
      {
        ssc::MaterialPointHistory history{make_array_view(
                                            std::as_const(committed)),
                                          make_array_view(trial),
                                          step == 0 ? 0. : dt};
        for (unsigned int it = 0;; ++it)
          {
            AssertThrow(it < 20, ExcMessage("no convergence"));
            Tensor<2, 3> F = unit_symmetric_tensor<3>();
            F[0][1]        = gamma;
            SymmetricTensor<2, 3> tau;
            Tensor<4, 3>          a;
            law.isochoric_response_in_step(X, F, history, tau, a);
            const Tensor<2, 3> F_inv = invert(F);
            const double       residual =
              (Tensor<2, 3>(tau) * transpose(F_inv))[0][1] - P;
            if (std::abs(residual) < 1e-14 * P)
              break;
            // dP_xy / dF_xy = F^{-1}_yk a_xkxl F^{-1}_yl
            double slope = 0;
            for (unsigned int k = 0; k < 3; ++k)
              for (unsigned int l = 0; l < 3; ++l)
                slope += F_inv[1][k] * a[0][k][0][l] * F_inv[1][l];
            gamma -= residual / slope;
          }
        committed = trial;
        measure(step * dt, gamma);
      }
  }

  /// Runs @p creep(dt, measure) at four steps and prints the relative errors
  /// against @p exact at the times of interest and the observed order.
  template <typename Creep, typename Exact>
  void
  check(const std::string &name, const Creep &creep, const Exact &exact)
  {
    const std::vector<double> times = {1., 2.5, 5., 10.};
    deallog << name << ", held from 0 to 10 s" << std::endl;
    for (const double t : times)
      deallog << "  t = " << t
              << " s: strain / instantaneous strain = " << exact(t) / exact(0.)
              << " (closed form)" << std::endl;
    std::vector<std::vector<double>> errors;
    for (const double dt : {0.1, 0.05, 0.025, 0.0125})
      {
        errors.emplace_back();
        creep(dt, [&](const double t, const double strain) {
          for (const double wanted : times)
            if (std::abs(t - wanted) < 1e-9)
              errors.back().push_back(std::abs(strain - exact(t)) /
                                      std::abs(exact(t)));
        });
        deallog << "  dt = " << dt << " s: relative errors";
        for (const double error : errors.back())
          deallog << ' ' << std::setprecision(2) << error;
        deallog << std::setprecision(4) << std::endl;
      }
    // the order from the coarser steps: at the finest, the law's
    // nonlinearity and the round-off at these tiny strains (a few 1e-8) are
    // no longer far below the error
    deallog << "  observed order from dt = 0.1 to 0.025 s:";
    for (unsigned int k = 0; k < times.size(); ++k)
      deallog << ' ' << std::setprecision(2)
              << 0.5 * std::log2(errors[0][k] / errors[2][k]);
    deallog << std::setprecision(4) << std::endl;
    const std::vector<double> &previous = errors.back();
    deallog << "  finest step within 1e-6 of the closed form: "
            << (*std::max_element(previous.begin(), previous.end()) < 1e-6 ?
                  "yes" :
                  "NO")
            << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  deallog << std::setprecision(4);
  const auto   law   = ssc::make_material(block_layers().layer(0));
  const double mu    = law->moduli().shear_modulus;
  const double kappa = law->moduli().bulk_modulus;

  const double sigma = 3e-10;
  check(
    "uniaxial stress 3e-10 MPa on the block (force control)",
    [&](const double dt, const auto &measure) {
      uniaxial_block_creep(sigma, dt, measure);
    },
    [&](const double t) {
      return sigma * (creep_compliance(t, mu) / 3. + 1. / (9. * kappa));
    });

  const double P = 1e-6;
  check(
    "simple shear stress 1e-6 MPa at a material point",
    [&](const double dt, const auto &measure) {
      simple_shear_creep(*law, P, dt, measure);
    },
    [&](const double t) { return P * creep_compliance(t, mu); });
}
