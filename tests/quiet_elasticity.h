#ifndef ssc_tests_quiet_elasticity_h
#define ssc_tests_quiet_elasticity_h

// The pieces every unit test of the mechanics builds alike: a uniform square
// patch and a volume solver that prints nothing.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <iostream>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/mesh/background_mesh.h>

/// A square patch @p length mm wide with cells of @p cell_size mm, all of
/// them in the ungraded core.
inline ssc::MeshParameters
uniform_patch(const double length, const double cell_size)
{
  ssc::MeshParameters parameters;
  parameters.patch_length_x  = length;
  parameters.patch_length_y  = length;
  parameters.cell_size       = cell_size;
  parameters.core_half_width = 10;
  return parameters;
}

/// An ElasticSystem with a timer that never reports and an output stream
/// that is off; the system keeps a reference to the timer, so both live
/// beside it. The laws take the parameters of @p laws (their defaults if
/// not given).
struct QuietElasticity
{
  QuietElasticity(ssc::BackgroundMesh             &mesh,
                  const ssc::LayerStack           &layers,
                  const ssc::ElasticityParameters &parameters,
                  const ssc::LayerLawParameters   &laws = {})
    : timer(MPI_COMM_WORLD,
            std::cout,
            dealii::TimerOutput::never,
            dealii::TimerOutput::wall_times)
    , pcout(std::cout, false)
    , elasticity(mesh, ssc::LayerMaterials(layers, laws), parameters, timer)
  {}

  dealii::TimerOutput        timer;
  dealii::ConditionalOStream pcout;
  ssc::ElasticSystem         elasticity;
};

/// The L2 and H1 errors of the solution on @p mesh with @p exact prescribed
/// on its whole boundary: a patch test, when @p exact is a field every
/// discretisation represents (a linear one).
inline auto
patch_test_errors(ssc::BackgroundMesh                        &mesh,
                  const ssc::LayerStack                      &layers,
                  ssc::ElasticityParameters                   parameters,
                  const std::shared_ptr<dealii::Function<3>> &exact)
{
  parameters.linear_solver.tolerance = 1e-14;
  QuietElasticity     quiet(mesh, layers, parameters);
  ssc::ElasticSystem &elasticity = quiet.elasticity;
  elasticity.field().distribute_dofs();
  std::vector<ssc::DirichletCondition> conditions;
  for (dealii::types::boundary_id id = 0; id < 6; ++id)
    conditions.push_back({id, dealii::ComponentMask(3, true), exact, {}});
  elasticity.setup(conditions);
  solve_linear(elasticity);
  return elasticity.field().errors(*exact);
}

#endif
