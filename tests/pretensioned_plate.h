#ifndef ssc_tests_pretensioned_plate_h
#define ssc_tests_pretensioned_plate_h

// A pre-tensioned thin plate (1 mm, one neo-Hookean layer, E 1 MPa, nu
// 0.3) with a cut or a hole at its centre, its sides on rollers holding the
// pre-tension, ramped in by Newton's method with adaptive load steps: the
// plate of tests/incision_plate and tests/hole_prestretched_sheet.

#include <deal.II/base/function.h>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/mesh/background_mesh.h>
#include <ssc/nonlinear/elastic_problem.h>
#include <ssc/nonlinear/load_stepping.h>
#include <ssc/nonlinear/newton_solver.h>
#include <ssc/scenes/wound.h>

#include "quiet_elasticity.h"

namespace pretensioned_plate
{
  using namespace dealii;

  constexpr double E = 1, nu = 0.3;

  /// The plate's layer: 1 mm thick (one cell across), E, nu,
  /// neo-Hookean, prestretch @p s.
  inline ssc::LayerStack
  plate_layers(const double s)
  {
    ssc::LayerStack layers;
    layers.add_layer("plate", ssc::LayerKind::skin, "1", E, nu, 1);
    layers.set_model(0, "neo-Hookean");
    layers.set_prestretch(0, s);
    return layers;
  }

  /**
   * The wound of a @p width mm square plate with prestretch @p s and cells
   * of @p h mm near its centre (graded by 1.25 outwards), cut by an
   * incision of length 2a along y, or with a hole of diameter 2a excised
   * (@p hole; the mesh lines fitted to its edge), at full pre-tension.
   */
  inline ssc::WoundShape
  cut_plate(const double h,
            const bool   hole,
            const double s,
            const double a,
            const double width)
  {
    const ssc::LayerStack layers = plate_layers(s);
    ssc::MeshParameters   mesh_parameters;
    mesh_parameters.patch_length_x  = width;
    mesh_parameters.patch_length_y  = width;
    mesh_parameters.cell_size       = h;
    mesh_parameters.core_half_width = hole ? 2 * a : 6;
    mesh_parameters.grading_ratio   = 1.25;
    ssc::Incision incision;
    incision.length       = 2 * a;
    incision.direction    = 1;
    incision.n_cut_layers = 1;
    if (hole)
      {
        incision.shape                       = ssc::Incision::Shape::disc;
        mesh_parameters.fitted_circle_radius = a;
      }
    ssc::BackgroundMesh mesh(layers,
                             mesh_parameters,
                             MPI_COMM_WORLD,
                             ssc::ResourceLimits(),
                             false,
                             incision);
    mesh.build();

    ssc::ElasticityParameters parameters;
    parameters.linear_solver.preconditioner =
      ssc::DisplacementPreconditioner::ldlt;
    parameters.linear_solver.tolerance = 1e-12;
    QuietElasticity     quiet(mesh, layers, parameters);
    ssc::ElasticSystem &plate = quiet.elasticity;
    plate.field().distribute_dofs();
    const auto zero = std::make_shared<Functions::ZeroFunction<3>>(3);
    std::vector<ssc::DirichletCondition> rollers;
    for (const unsigned int d : {0u, 1u, 2u})
      {
        ComponentMask component(3, false);
        component.set(d, true);
        rollers.push_back(
          {static_cast<types::boundary_id>(2 * d), component, zero, {}});
        if (d < 2)
          rollers.push_back(
            {static_cast<types::boundary_id>(2 * d + 1), component, zero, {}});
      }
    plate.setup(rollers);

    ssc::NewtonParameters newton_parameters;
    newton_parameters.relative_tolerance = 1e-10;
    ssc::ElasticProblem problem(plate);
    ssc::NewtonSolver   newton(problem, newton_parameters, quiet.pcout, false);
    ssc::LoadStepper    stepper(newton);
    double              increment = 1;
    stepper.follow(
      0.,
      1.,
      increment,
      [&plate](const double f) { plate.set_prestretch_fraction(f); },
      ssc::LoadDependence::tangent);
    return ssc::measure_wound(plate.field(), incision);
  }
} // namespace pretensioned_plate

#endif
