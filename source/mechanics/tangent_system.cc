#include <ssc/mechanics/tangent_system.h>

namespace ssc
{
  TangentSystem::TangentSystem(const ElasticityParameters &parameters,
                               const DisplacementField    &field,
                               const BoundaryConstraints  &constraints,
                               TimerOutput                &timer,
                               ConditionalOStream         *progress)
    : parameters(parameters)
    , field(field)
    , constraints(constraints)
    , timer(timer)
    , linear_solver(parameters.linear_solver, field, constraints, progress)
  {}


  void
  TangentSystem::setup(const TrilinosWrappers::SparsityPattern &sparsity)
  {
    const IndexSet &owned = field.locally_owned_dofs();
    const MPI_Comm  communicator =
      field.dof_handler().get_triangulation().get_communicator();
    linearisation.tangent.reinit(sparsity);
    linear_solver.matrix_reinitialized();
    if (parameters.linear_solver.method == LinearSolverMethod::block)
      {
        pressure =
          std::make_unique<PressureSystem>(field.dof_handler(),
                                           parameters.n_pressure_modes());
        pressure->setup(sparsity, constraints.prescribed());
      }
    linearisation.rhs.reinit(owned, communicator);
    linearisation.update.reinit(owned, communicator);
  }


  LinearSolveReport
  TangentSystem::solve_update(const SolveTarget &target)
  {
    TimerOutput::Scope t(timer, "solve");
    linearisation.update = 0;
    if (pressure)
      return linear_solver.solve_saddle_point(linearisation.tangent,
                                              *pressure,
                                              linearisation.update,
                                              linearisation.rhs,
                                              constraints.increment(),
                                              target);
    return linear_solver.solve(linearisation.tangent,
                               linearisation.update,
                               linearisation.rhs,
                               constraints.increment(),
                               target);
  }


  TruncatedCGReport
  TangentSystem::solve_update_within(const double       radius,
                                     const SolveTarget &target,
                                     const bool         new_preconditioner)
  {
    TimerOutput::Scope t(timer, "solve");
    return linear_solver.solve_within(linearisation.tangent,
                                      linearisation.update,
                                      linearisation.rhs,
                                      constraints.increment(),
                                      radius,
                                      target,
                                      new_preconditioner);
  }


  void
  TangentSystem::shift_tangent(const double shift)
  {
    // read the diagonal before the first add leaves the matrix uncompressed
    TrilinosWrappers::SparseMatrix  &K         = linearisation.tangent;
    const AffineConstraints<double> &increment = constraints.increment();
    std::vector<std::pair<types::global_dof_index, double>> additions;
    for (const types::global_dof_index row : field.locally_owned_dofs())
      if (!increment.is_constrained(row))
        additions.emplace_back(row, shift * K.diag_element(row));
    for (const auto &[row, value] : additions)
      K.add(row, row, value);
    K.compress(VectorOperation::add);
  }
} // namespace ssc
