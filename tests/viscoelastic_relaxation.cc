// The visco-elastic law (a neo-Hookean layer with a two-term deviatoric
// Prony series, ViscoelasticMaterial) through the whole mechanics: a 2 x 2
// x 2 mm block of 8 cells whose every face is moved homogeneously, u =
// s(t) A X, ramped to s_max over 1 s and held to 10 s, time step dt. Two
// loadings: confined uniaxial stretch (A = e_x e_x, to s = 0.3) and simple
// shear (A = e_x e_y, to s = 0.5). The interior node is solved by Newton's
// method. The block's mean first Piola stress is measured by virtual work
// from the nodal residual, sum_i r_i x_j / V = mean P_cj, and compared
// with the closed form of the same law at the homogeneous F(t):
//   S(t) = S_vol + g_inf S_0(t) + sum_i g_i H_i(t),
//   H_i(t) = S_0(T) e^{-(t-T)/tau_i} - 1/tau_i int_0^T e^{-(t-s)/tau_i}
//            S_0(s) ds   (T = min(t, t_ramp), by parts),
// the integral by composite Gauss quadrature far finer than any step, S_0
// = mu F^{-1} dev(J^{-2/3} F F^T) F^{-T}. Printed: the relative error at
// four times for dt = 0.1, 0.05, 0.025, 0.0125 s and the observed order (the
// integration is second order). Then the elastic limits: tau -> 0 gives
// the long-term neo-Hookean (mu g_inf, the same bulk modulus) and tau ->
// infinity the instantaneous one, both solved as elastic blocks; and the
// law's tangent against central differences of its stress at a state with
// history, mid-relaxation.

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>

#include <ssc/materials/viscoelastic_material.h>
#include <ssc/nonlinear/elastic_problem.h>
#include <ssc/nonlinear/newton_solver.h>

#include "quiet_elasticity.h"
#include "tests.h"

using namespace dealii;

namespace
{
  constexpr double E      = 0.01;
  constexpr double nu     = 0.45;
  constexpr double t_ramp = 1.;
  constexpr double t_end  = 10.;

  const ssc::PronySeries prony{{0.3, 0.2}, {0.5, 5.}};

  /// u = A X.
  class LinearField : public Function<3>
  {
  public:
    explicit LinearField(const Tensor<2, 3> &A)
      : Function<3>(3)
      , A(A)
    {}

    double
    value(const Point<3> &p, const unsigned int c) const override
    {
      return (A * p)[c];
    }

  private:
    const Tensor<2, 3> A;
  };

  double
  ramp(const double t)
  {
    return std::min(t / t_ramp, 1.);
  }

  /// The isochoric second Piola stress of the instantaneous neo-Hookean.
  SymmetricTensor<2, 3>
  S_0(const Tensor<2, 3> &F, const double mu)
  {
    const SymmetricTensor<2, 3> b =
      std::pow(determinant(F), -2. / 3.) * symmetrize(F * transpose(F));
    const Tensor<2, 3> F_inv = invert(F);
    return symmetrize(F_inv * Tensor<2, 3>(mu * deviator(b)) *
                      transpose(F_inv));
  }

  /// The closed form's first Piola stress at time @p t.
  Tensor<2, 3>
  closed_form_piola(const Tensor<2, 3>          &A,
                    const double                 s_max,
                    const double                 t,
                    const ssc::VolumetricEnergy &volumetric,
                    const double                 mu)
  {
    const auto F_at = [&](const double time) {
      return unit_symmetric_tensor<3>() + s_max * ramp(time) * A;
    };
    const Tensor<2, 3>    F = F_at(t);
    const double          T = std::min(t, t_ramp);
    SymmetricTensor<2, 3> S = prony.long_term_fraction() * S_0(F, mu);
    const QGauss<1>       gauss(4);
    const unsigned int    n_intervals = 2000;
    for (unsigned int i = 0; i < prony.size(); ++i)
      {
        const double          tau = prony.relaxation_times[i];
        SymmetricTensor<2, 3> integral;
        for (unsigned int k = 0; k < n_intervals; ++k)
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double h    = T / n_intervals;
              const double time = (k + gauss.point(q)[0]) * h;
              integral += gauss.weight(q) * h * std::exp(-(t - time) / tau) *
                          S_0(F_at(time), mu);
            }
        const SymmetricTensor<2, 3> H =
          std::exp(-(t - T) / tau) * S_0(F_at(T), mu) - integral / tau;
        S += prony.relative_moduli[i] * H;
      }
    const double J = determinant(F);
    S +=
      volumetric.pressure(J) * J * symmetrize(invert(F) * transpose(invert(F)));
    return F * Tensor<2, 3>(S);
  }

  /// A block of 8 cells of the layer "block" with @p series (none: elastic)
  /// at the moduli @p E_block, @p nu_block.
  ssc::LayerStack
  block_layers(const double            E_block,
               const double            nu_block,
               const ssc::PronySeries &series)
  {
    ssc::LayerStack layers;
    layers.add_layer("block", ssc::LayerKind::SAT, "2", E_block, nu_block, 2);
    layers.set_model(0, "neo-Hookean");
    layers.set_viscoelasticity(0,
                               series.relative_moduli,
                               series.relaxation_times);
    return layers;
  }

  /// Moves the faces of a block of @p layers by s(t) A X over [0, t_end]
  /// in steps @p dt and calls @p measure(t, mean P) after each of the steps
  /// for which @p wanted(t) holds.
  template <typename Wanted, typename Measure>
  void
  run_block(const ssc::LayerStack &layers,
            const Tensor<2, 3>    &A,
            const double           s_max,
            const double           dt,
            const Wanted          &wanted,
            const Measure         &measure)
  {
    ssc::BackgroundMesh mesh(layers, uniform_patch(2, 1), MPI_COMM_WORLD);
    mesh.build();
    ssc::ElasticityParameters parameters;
    parameters.formulation             = ssc::Formulation::displacement;
    parameters.linear_solver.tolerance = 1e-13;
    ssc::NewtonParameters newton_parameters;
    newton_parameters.relative_tolerance = 1e-13;
    newton_parameters.absolute_tolerance = 1e-16;
    QuietElasticity     quiet(mesh, layers, parameters);
    ssc::ElasticSystem &elasticity = quiet.elasticity;
    elasticity.field().distribute_dofs();
    const auto field = std::make_shared<LinearField>(A);
    std::vector<ssc::DirichletCondition> conditions;
    for (types::boundary_id id = 0; id < 6; ++id)
      conditions.push_back({id, ComponentMask(3, true), field, {}});
    elasticity.setup(conditions);
    ssc::ElasticProblem problem(elasticity);
    ssc::NewtonSolver   newton(problem, newton_parameters, quiet.pcout, false);

    // the dofs of the vertices and their positions, once each
    std::vector<std::pair<types::global_dof_index, Point<3>>> vertex_dofs;
    std::set<types::global_dof_index>                         seen;
    const auto &field_dofs = elasticity.field();
    for (const auto &cell : field_dofs.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (const auto dof : field_dofs.vertex_dofs(cell, v))
            if (field_dofs.locally_owned_dofs().is_element(dof) &&
                seen.insert(dof).second)
              vertex_dofs.emplace_back(dof, cell->vertex(v));

    const unsigned int n_steps = std::lround(t_end / dt);
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        const double t = n * dt;
        elasticity.constraints().set_dirichlet_scale(s_max * ramp(t));
        elasticity.set_time(t);
        const ssc::NewtonReport report = newton.solve();
        AssertThrow(report.converged, ExcMessage(report.failure));
        AssertThrow(problem.accept_state(), ExcInternalError());
        if (!wanted(t))
          continue;
        const TrilinosWrappers::MPI::Vector r = elasticity.nodal_residual();
        Tensor<2, 3>                        P;
        for (const auto &[dof, X] : vertex_dofs)
          {
            const unsigned int c = elasticity.constraints().component(dof);
            for (unsigned int j = 0; j < 3; ++j)
              P[c][j] += r[dof] * X[j];
          }
        P = Utilities::MPI::sum(P, MPI_COMM_WORLD) / 8.; // V = 8 mm^3
        measure(t, P);
      }
  }

  /// The one component of P that a loading is about.
  struct Loading
  {
    std::string  name;
    Tensor<2, 3> A;
    double       s_max;
    unsigned int i, j;
  };

  /// The tangent of the law at a state with history, against central
  /// differences of its stress (first Piola, pulled back from tau).
  void
  check_tangent()
  {
    const ssc::LayerStack layers = block_layers(E, nu, prony);
    const auto            law    = ssc::make_material(layers.layer(0));
    const unsigned int    n      = law->n_history_variables();
    std::vector<double>   committed(n), trial(n), scratch(n);
    const Point<3>        X;
    // one step of 0.3 s to a shear-stretch state writes the history
    Tensor<2, 3> F0 = unit_symmetric_tensor<3>();
    F0[0][1]        = 0.4;
    F0[0][0]        = 1.2;
    ssc::MaterialPointHistory first{make_array_view(std::as_const(committed)),
                                    make_array_view(trial),
                                    0.3};
    SymmetricTensor<2, 3>     tau;
    Tensor<4, 3>              a;
    law->isochoric_response_in_step(X, F0, first, tau, a);
    committed = trial;
    // the next step, 0.2 s, to another F
    Tensor<2, 3> F = F0;
    F[1][2] += 0.15;
    F[2][2] -= 0.1;
    ssc::MaterialPointHistory step{make_array_view(std::as_const(committed)),
                                   make_array_view(scratch),
                                   0.2};
    law->isochoric_response_in_step(X, F, step, tau, a);
    const auto piola = [&](const Tensor<2, 3> &G) {
      return Tensor<2, 3>(law->isochoric_stress_in_step(X, G, step)) *
             transpose(invert(G));
    };
    const double h             = 1e-6;
    double       largest_error = 0, largest = 0;
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int L = 0; L < 3; ++L)
        {
          Tensor<2, 3> plus(F), minus(F);
          plus[j][L] += h;
          minus[j][L] -= h;
          const Tensor<2, 3> dP = (piola(plus) - piola(minus)) / (2 * h);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int K = 0; K < 3; ++K)
              {
                // A_iKjL from the spatial tangent: F^{-1} on k and l
                double             A     = 0;
                const Tensor<2, 3> F_inv = invert(F);
                for (unsigned int k = 0; k < 3; ++k)
                  for (unsigned int l = 0; l < 3; ++l)
                    A += F_inv[K][k] * a[i][k][j][l] * F_inv[L][l];
                largest_error = std::max(largest_error, std::abs(A - dP[i][K]));
                largest       = std::max(largest, std::abs(dP[i][K]));
              }
        }
    deallog << "tangent at a state with history, relative to finite "
               "differences: "
            << (largest_error / largest < 1e-6 ? "below 1e-6" : "WRONG")
            << std::endl;
    // the stress alone is the stress of the response
    deallog << "stress alone = stress of the response: "
            << ((Tensor<2, 3>(law->isochoric_stress_in_step(X, F, step) - tau))
                      .norm() < 1e-12 * tau.norm() ?
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
  const ssc::LayerStack     layers = block_layers(E, nu, prony);
  const auto                law    = ssc::make_material(layers.layer(0));
  const double              mu     = law->moduli().shear_modulus;
  const std::vector<double> times  = {1., 1.5, 5., 10.};

  Tensor<2, 3> uniaxial, shear;
  uniaxial[0][0] = 1.;
  shear[0][1]    = 1.;
  for (const Loading &loading :
       {Loading{"confined uniaxial stretch", uniaxial, 0.3, 0, 0},
        Loading{"simple shear", shear, 0.5, 0, 1}})
    {
      deallog << loading.name << " to " << loading.s_max
              << " in 1 s, held to 10 s" << std::endl;
      std::vector<double> previous;
      for (const double dt : {0.1, 0.05, 0.025, 0.0125})
        {
          std::vector<double> errors;
          run_block(
            layers,
            loading.A,
            loading.s_max,
            dt,
            [&](const double t) {
              for (const double wanted : times)
                if (std::abs(t - wanted) < 1e-9)
                  return true;
              return false;
            },
            [&](const double t, const Tensor<2, 3> &P) {
              const Tensor<2, 3> exact = closed_form_piola(
                loading.A, loading.s_max, t, law->volumetric(), mu);
              const double reference = exact[loading.i][loading.j];
              errors.push_back(std::abs(P[loading.i][loading.j] - reference) /
                               std::abs(reference));
              if (dt == 0.1)
                deallog << "  t = " << t << " s: P = " << std::setprecision(6)
                        << reference << std::setprecision(4)
                        << " MPa (closed form), relaxed to "
                        << reference /
                             closed_form_piola(loading.A,
                                               loading.s_max,
                                               t_ramp,
                                               law->volumetric(),
                                               mu)[loading.i][loading.j]
                        << " of its value at 1 s" << std::endl;
            });
          deallog << "  dt = " << dt << " s: relative errors";
          for (unsigned int k = 0; k < errors.size(); ++k)
            deallog << ' ' << errors[k];
          if (!previous.empty())
            {
              deallog << ", order";
              for (unsigned int k = 0; k < errors.size(); ++k)
                deallog << ' ' << std::setprecision(2)
                        << std::log2(previous[k] / errors[k])
                        << std::setprecision(4);
            }
          deallog << std::endl;
          previous = errors;
        }
      deallog << "  finest step within 1e-6 of the closed form: "
              << (*std::max_element(previous.begin(), previous.end()) < 1e-6 ?
                    "yes" :
                    "NO")
              << std::endl;

      // the elastic limits: tau -> 0 and tau -> infinity, at the end
      const double kappa   = law->moduli().bulk_modulus;
      const double mu_long = prony.long_term_fraction() * mu;
      const double E_long  = 9 * kappa * mu_long / (3 * kappa + mu_long);
      const double nu_long =
        (3 * kappa - 2 * mu_long) / (2 * (3 * kappa + mu_long));
      for (const auto &[name, tau, E_elastic, nu_elastic] :
           {std::make_tuple(
              std::string("tau -> 0 (1e-9 s)"), 1e-9, E_long, nu_long),
            std::make_tuple(
              std::string("tau -> infinity (1e12 s)"), 1e12, E, nu)})
        {
          const ssc::PronySeries limit{prony.relative_moduli, {tau, tau}};
          double                 viscous = 0, elastic = 0;
          const auto             at_end = [](const double t) {
            return std::abs(t - t_end) < 1e-9;
          };
          run_block(block_layers(E, nu, limit),
                    loading.A,
                    loading.s_max,
                    0.5,
                    at_end,
                    [&](double, const Tensor<2, 3> &P) {
                      viscous = P[loading.i][loading.j];
                    });
          run_block(block_layers(E_elastic, nu_elastic, {}),
                    loading.A,
                    loading.s_max,
                    0.5,
                    at_end,
                    [&](double, const Tensor<2, 3> &P) {
                      elastic = P[loading.i][loading.j];
                    });
          deallog << "  " << name
                  << ": P / elastic P = " << std::setprecision(10)
                  << viscous / elastic << std::setprecision(4) << std::endl;
        }
    }
  check_tangent();
}
