#include <deal.II/fe/fe_tools.h>

#include <deal.II/lac/vector.h>

#include <limits>

#include <ssc/base/user_message.h>
#include <ssc/scenes/enriched_depth_estimate.h>

namespace ssc
{
  namespace
  {
    /// The next richer discretisation of @p parameters' Q1 scene: Q2-P0.
    std::vector<std::string>
    enriched_overrides(const Parameters &parameters)
    {
      // Parameters::check_formulation() allows Q1 scenes only
      Assert(parameters.elasticity.degree == 1, ExcInternalError());
      // Q2-P0: the dilatation space of the scene (Q1-P0) kept, so that the
      // richer spaces contain the scene's; with P1 the cell-wise variation
      // of J that Q1-P0 leaves free would carry bulk energy at once
      return {"Elasticity/Degree=" +
                std::to_string(parameters.elasticity.degree + 1),
              "Elasticity/Formulation=mean dilatation"};
    }
  } // namespace


  EnrichedDepthEstimate::EnrichedDepthEstimate(const Parameters &parameters,
                                               const MPI_Comm mpi_communicator)
    : enriched(parameters, enriched_overrides(parameters), mpi_communicator)
  {}


  std::string
  EnrichedDepthEstimate::method() const
  {
    return "one Newton step of Q2-P0 from the converged Q1 state";
  }


  types::global_dof_index
  EnrichedDepthEstimate::n_dofs()
  {
    return enriched.system().field().dof_handler().n_dofs();
  }


  void
  EnrichedDepthEstimate::interpolate_state(const ElasticSystem &system)
  {
    const DoFHandler<3> &coarse     = system.field().dof_handler();
    DisplacementField   &rich_field = enriched.system().field();
    const DoFHandler<3> &rich       = rich_field.dof_handler();
    if (interpolation.m() == 0)
      {
        interpolation.reinit(rich.get_fe().n_dofs_per_cell(),
                             coarse.get_fe().n_dofs_per_cell());
        FETools::get_interpolation_matrix(coarse.get_fe(),
                                          rich.get_fe(),
                                          interpolation);
      }

    TrilinosWrappers::MPI::Vector u      = rich_field.owned_solution();
    const IndexSet               &owned  = rich_field.locally_owned_dofs();
    const auto                   &source = system.field().solution();
    Vector<double>                coarse_values(interpolation.n());
    Vector<double>                rich_values(interpolation.m());
    std::vector<types::global_dof_index> rich_dofs(interpolation.m());
    auto                                 rich_cell = rich.begin_active();
    for (const auto &cell : coarse.active_cell_iterators())
      {
        AssertThrow(rich_cell != rich.end() &&
                      cell->center().distance(rich_cell->center()) <=
                        1e-9 * cell->diameter(),
                    ExcInternalError("the enriched mesh differs from the "
                                     "scene's"));
        if (cell->is_locally_owned())
          {
            cell->get_dof_values(source, coarse_values);
            interpolation.vmult(rich_values, coarse_values);
            rich_cell->get_dof_indices(rich_dofs);
            for (unsigned int i = 0; i < rich_dofs.size(); ++i)
              if (owned.is_element(rich_dofs[i]))
                u[rich_dofs[i]] = rich_values[i];
          }
        ++rich_cell;
      }
    u.compress(VectorOperation::insert);
    rich_field.set_solution(u);
  }


  double
  EnrichedDepthEstimate::error(const ElasticSystem &system,
                               const unsigned int,
                               const double force,
                               const double)
  {
    interpolate_state(system);
    // the prescribed values and ties (and hanging nodes) as the scene's
    PunchLoading &loading = enriched.loading();
    loading.apply(force);
    const double        depth  = loading.depth(force);
    const LinearSolver &solver = enriched.system().tangent_system().solver();
    const unsigned int  indefinite = solver.indefinite_factorizations();
    failure.clear();
    try
      {
        solve_linear(enriched.system());
      }
    catch (const ExceptionBase &error)
      {
        // the estimate's solve is not the scene's: the scene goes on
        failure = "its Q2-P0 solve failed: " + user_message(error);
        return std::numeric_limits<double>::quiet_NaN();
      }
    // a step along negative curvature is no estimate of anything
    if (solver.indefinite_factorizations() > indefinite)
      {
        failure = "the Q2-P0 tangent at this state is indefinite";
        return std::numeric_limits<double>::quiet_NaN();
      }
    return loading.depth(force) - depth;
  }
} // namespace ssc
