#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <limits>

#include <ssc/mechanics/elastic_system.h>

namespace ssc
{
  ElasticSystem::ElasticSystem(const BackgroundMesh       &mesh,
                               const LayerStack           &layers,
                               const ElasticityParameters &parameters,
                               TimerOutput                &timer,
                               ConditionalOStream         *progress)
    : parameters(parameters)
    , timer(timer)
    , layer_materials(layers)
    , displacement(mesh.triangulation(),
                   parameters.degree,
                   mesh.mapping_degree(parameters.degree))
    , boundary_constraints(displacement)
    , growth_field(QGauss<3>(parameters.degree + 1))
    , kernel(layer_materials, parameters, growth_field)
    , assembler(displacement, kernel)
    , linear_solver(parameters.linear_solver,
                    displacement,
                    boundary_constraints,
                    progress)
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
    return accepted;
  }


  void
  ElasticSystem::reject_state()
  {
    for (DofContribution *contribution : dof_contributions)
      contribution->reject();
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
  ElasticSystem::setup(const std::vector<DirichletCondition> &conditions,
                       const std::vector<TiedCondition>      &ties)
  {
    boundary_constraints.setup(conditions, ties);
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
    matrix.reinit(sparsity);
    if (parameters.linear_solver.method == LinearSolverMethod::block)
      {
        pressure_system =
          std::make_unique<PressureSystem>(displacement.dof_handler(),
                                           parameters.n_pressure_modes());
        pressure_system->setup(sparsity, boundary_constraints.prescribed());
      }
    system_rhs.reinit(owned, communicator);
    last_update.reinit(owned, communicator);
  }


  void
  ElasticSystem::apply_constraints()
  {
    TrilinosWrappers::MPI::Vector owned = displacement.owned_solution();
    boundary_constraints.prescribed().distribute(owned);
    displacement.set_solution(owned);
  }


  double
  ElasticSystem::assemble(const bool with_tangent)
  {
    TimerOutput::Scope               t(timer, "assembly");
    const AffineConstraints<double> &constraints =
      with_tangent ? boundary_constraints.update_from(displacement.solution()) :
                     boundary_constraints.homogeneous();
    const unsigned int inverted =
      assembler.assemble(displacement.solution(),
                         constraints,
                         external_loads.body_force,
                         with_tangent ? &matrix : nullptr,
                         system_rhs,
                         pressure_system.get());
    for (const auto &[dof, force] : external_loads.nodal_forces)
      if (displacement.locally_owned_dofs().is_element(dof))
        system_rhs[dof] += force;
    system_rhs.compress(VectorOperation::add);
    if (inverted > 0)
      return std::numeric_limits<double>::infinity();
    return system_rhs.l2_norm();
  }


  LinearSolveReport
  ElasticSystem::solve_update(const SolveTarget &target)
  {
    TimerOutput::Scope t(timer, "solve");
    last_update = 0;
    if (pressure_system)
      return linear_solver.solve_saddle_point(matrix,
                                              *pressure_system,
                                              last_update,
                                              system_rhs,
                                              boundary_constraints.increment(),
                                              target);
    return linear_solver.solve(matrix,
                               last_update,
                               system_rhs,
                               boundary_constraints.increment(),
                               target);
  }


  TruncatedCGReport
  ElasticSystem::solve_update_within(const double       radius,
                                     const SolveTarget &target,
                                     const bool         new_preconditioner)
  {
    TimerOutput::Scope t(timer, "solve");
    return linear_solver.solve_within(matrix,
                                      last_update,
                                      system_rhs,
                                      boundary_constraints.increment(),
                                      radius,
                                      target,
                                      new_preconditioner);
  }


  LinearSolveReport
  ElasticSystem::solve_linear()
  {
    assemble(true);
    const LinearSolveReport       report = solve_update(SolveTarget());
    TrilinosWrappers::MPI::Vector u      = displacement.owned_solution();
    u += last_update;
    displacement.set_solution(u);
    return report;
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


  double
  ElasticSystem::volume_change() const
  {
    FEValues<3>                      fe_values(displacement.mapping(),
                          displacement.fe(),
                          kernel.quadrature(),
                          update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector u(0);
    std::vector<Tensor<2, 3>>        gradients(kernel.quadrature().size());
    double                           change = 0;
    for (const auto &cell : displacement.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_gradients(displacement.solution(),
                                              gradients);
          const bool small_strain =
            kernel.material(cell).kinematics() == Kinematics::small_strain;
          for (unsigned int q = 0; q < gradients.size(); ++q)
            change +=
              (small_strain ?
                 trace(gradients[q]) :
                 determinant(unit_symmetric_tensor<3>() + gradients[q]) - 1.) *
              fe_values.JxW(q);
        }
    return Utilities::MPI::sum(
      change,
      displacement.dof_handler().get_triangulation().get_communicator());
  }
} // namespace ssc
