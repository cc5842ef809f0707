#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <limits>

#include <ssc/base/collective_error.h>
#include <ssc/mechanics/elastic_system.h>

namespace ssc
{
  ElasticSystem::ElasticSystem(const BackgroundMesh       &mesh,
                               LayerMaterials              materials,
                               const ElasticityParameters &parameters,
                               TimerOutput                &timer,
                               ConditionalOStream         *progress)
    : parameters(parameters)
    , timer(timer)
    , layer_materials(std::move(materials))
    , displacement(mesh.triangulation(),
                   parameters.degree,
                   mesh.mapping_degree(parameters.degree))
    , boundary_constraints(displacement)
    , growth_field(QGauss<3>(parameters.degree + 1))
    , kernel(layer_materials, parameters, growth_field, point_history)
    , assembler(displacement, kernel)
    , tangent(parameters, displacement, boundary_constraints, timer, progress)
  {}


  void
  ElasticSystem::attach(const CellContribution &contribution)
  {
    assembler.attach(contribution);
  }


  void
  ElasticSystem::attach(DofContribution &contribution)
  {
    assembler.attach(contribution);
    dof_contributions.push_back(&contribution);
  }


  bool
  ElasticSystem::accept_state()
  {
    bool accepted = true;
    for (DofContribution *contribution : dof_contributions)
      accepted = contribution->accept(displacement.solution()) && accepted;
    if (accepted)
      accepted_time = solved_time;
    if (accepted && !point_history.empty())
      {
        // the last assembly may have been at a rejected trial state (line
        // search, trust region): the history to commit is the one of the
        // accepted state, which a residual assembly writes
        nodal_residual();
        point_history.accept();
      }
    return accepted;
  }


  void
  ElasticSystem::reject_state()
  {
    for (DofContribution *contribution : dof_contributions)
      contribution->reject();
    point_history.reject();
  }


  TrilinosWrappers::MPI::Vector
  ElasticSystem::nodal_residual()
  {
    TimerOutput::Scope            t(timer, "assembly");
    TrilinosWrappers::MPI::Vector rhs(
      displacement.locally_owned_dofs(),
      displacement.triangulation().get_communicator());
    assembler.assemble(displacement.solution(),
                       boundary_constraints.hanging_nodes(),
                       external_loads.body_force,
                       nullptr,
                       rhs);
    rhs *= -1.;
    return rhs;
  }


  void
  ElasticSystem::check_laws_at_quadrature_points() const
  {
    FEValues<3> fe_values(displacement.mapping(),
                          displacement.fe(),
                          kernel.quadrature(),
                          update_quadrature_points);
    run_collectively(
      [&]() {
        for (const auto &cell :
             displacement.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              for (const Point<3> &X : fe_values.get_quadrature_points())
                layer_materials[cell->material_id()].check_point(X);
            }
      },
      displacement.dof_handler().get_triangulation().get_communicator());
  }


  void
  ElasticSystem::setup(const std::vector<DirichletCondition> &conditions,
                       const std::vector<TiedCondition>      &ties)
  {
    std::vector<std::pair<types::global_dof_index, unsigned int>> extra;
    for (const DofContribution *contribution : dof_contributions)
      for (const auto &dof : contribution->extra_relevant_dofs())
        extra.push_back(dof);
    boundary_constraints.setup(conditions, ties, extra);
    std::vector<unsigned int> n_history_variables;
    for (unsigned int m = 0; m < layer_materials.size(); ++m)
      n_history_variables.push_back(layer_materials[m].n_history_variables());
    point_history.initialize(displacement.dof_handler().get_triangulation(),
                             n_history_variables,
                             Utilities::pow(parameters.degree + 1, 3));
    check_laws_at_quadrature_points();
    displacement.set_relevant_dofs(boundary_constraints.relevant_dofs());
    const IndexSet &owned = displacement.locally_owned_dofs();
    const MPI_Comm  communicator =
      displacement.dof_handler().get_triangulation().get_communicator();
    // Built directly in Trilinos' compressed format: a DynamicSparsityPattern
    // would double the peak memory of this step.
    TrilinosWrappers::SparsityPattern sparsity(
      owned, owned, boundary_constraints.relevant_dofs(), communicator);
    DoFTools::make_sparsity_pattern(displacement.dof_handler(),
                                    sparsity,
                                    boundary_constraints.prescribed(),
                                    false,
                                    Utilities::MPI::this_mpi_process(
                                      communicator));
    assembler.add_couplings(boundary_constraints.prescribed(), sparsity);
    sparsity.compress();
    tangent.setup(sparsity);
  }


  double
  ElasticSystem::assemble(const bool with_tangent)
  {
    TimerOutput::Scope               t(timer, "assembly");
    LinearisedSystem                &linearisation = tangent.linearised();
    const AffineConstraints<double> &constraints =
      with_tangent ? boundary_constraints.update_from(displacement.solution()) :
                     boundary_constraints.homogeneous();
    const unsigned int inverted =
      assembler.assemble(displacement.solution(),
                         constraints,
                         external_loads.body_force,
                         with_tangent ? &linearisation.tangent : nullptr,
                         linearisation.rhs,
                         tangent.pressure_system());
    for (const auto &[dof, force] : external_loads.nodal_forces)
      if (displacement.locally_owned_dofs().is_element(dof))
        linearisation.rhs[dof] += force;
    linearisation.rhs.compress(VectorOperation::add);
    if (inverted > 0)
      return std::numeric_limits<double>::infinity();
    return linearisation.rhs.l2_norm();
  }


  Tensor<1, 3>
  ElasticSystem::reaction(const unsigned int condition)
  {
    TimerOutput::Scope t(timer, "assembly");
    // Virtual work of the residual against a unit field w on the
    // condition's dofs, extended to the hanging nodes that depend on them:
    // only the cells that touch its support contribute.
    const IndexSet &owned = displacement.locally_owned_dofs();
    const MPI_Comm  communicator =
      displacement.dof_handler().get_triangulation().get_communicator();
    TrilinosWrappers::MPI::Vector unit(owned, communicator);
    for (const auto dof : boundary_constraints.dofs_of(condition))
      if (owned.is_element(dof))
        unit[dof] = 1.;
    unit.compress(VectorOperation::insert);
    boundary_constraints.hanging_nodes().distribute(unit);
    TrilinosWrappers::MPI::Vector weight(owned,
                                         boundary_constraints.relevant_dofs(),
                                         communicator);
    weight = unit;
    return assembler.weighted_residual(
      displacement.solution(),
      weight,
      external_loads.body_force,
      [this](const types::global_dof_index dof) {
        return boundary_constraints.component(dof);
      });
  }


  LinearSolveReport
  solve_linear(ElasticSystem &system)
  {
    system.assemble(true);
    TangentSystem                &tangent = system.tangent_system();
    const LinearSolveReport       report  = tangent.solve_update(SolveTarget());
    TrilinosWrappers::MPI::Vector u       = system.field().owned_solution();
    u += tangent.linearised().update;
    system.field().set_solution(u);
    return report;
  }
} // namespace ssc
