#include <cmath>

#include <ssc/nonlinear/elastic_problem.h>

namespace ssc
{
  ElasticProblem::ElasticProblem(ElasticSystem &system)
    : system(system)
  {}


  double
  ElasticProblem::residual()
  {
    return system.assemble(false);
  }


  double
  ElasticProblem::tangent()
  {
    return system.assemble(true);
  }


  double
  ElasticProblem::rhs_norm() const
  {
    return system.tangent_system().linearised().rhs.l2_norm();
  }


  LinearSolveReport
  ElasticProblem::solve_update(const SolveTarget &target)
  {
    return system.tangent_system().solve_update(target);
  }


  TruncatedCGReport
  ElasticProblem::solve_update_within(const double       radius,
                                      const SolveTarget &target,
                                      const bool         new_tangent)
  {
    return system.tangent_system().solve_update_within(radius,
                                                       target,
                                                       new_tangent);
  }


  void
  ElasticProblem::shift_tangent(const double shift)
  {
    system.tangent_system().shift_tangent(shift);
  }


  ElasticProblem::VectorType
  ElasticProblem::free_update() const
  {
    VectorType du(system.tangent_system().linearised().update);
    system.constraints().increment().set_zero(du);
    return du;
  }


  double
  ElasticProblem::update_curvature() const
  {
    // with the constrained entries zeroed, du . K du is the quadratic form
    // of the condensed tangent
    const VectorType du = free_update();
    VectorType       K_du(du);
    system.tangent_system().linearised().tangent.vmult(K_du, du);
    const double norm = du * du;
    return norm > 0 ? (du * K_du) / norm : 0.;
  }


  double
  ElasticProblem::slope_along_update() const
  {
    // the right-hand side is -r, with zeros on the constrained rows
    return -(system.tangent_system().linearised().rhs *
             system.tangent_system().linearised().update);
  }


  void
  ElasticProblem::store_state()
  {
    stored_state = system.field().owned_solution();
  }


  void
  ElasticProblem::set_state_from_stored(const double step)
  {
    VectorType u(stored_state);
    u.add(step, system.tangent_system().linearised().update);
    system.field().set_solution(u);
  }


  void
  ElasticProblem::restore_state()
  {
    system.field().set_solution(stored_state);
  }


  ElasticProblem::VectorType
  ElasticProblem::state() const
  {
    return system.field().owned_solution();
  }


  void
  ElasticProblem::set_state(const VectorType &state)
  {
    system.field().set_solution(state);
  }


  double
  ElasticProblem::constraint_gap() const
  {
    return system.constraints().gap(system.field().solution());
  }


  double
  ElasticProblem::applied_load() const
  {
    double applied = 0.;
    for (const auto &force : system.loads().nodal_forces)
      applied += force.second * force.second;
    return std::sqrt(applied);
  }


  std::string
  ElasticProblem::describe_update() const
  {
    return system.field().describe(free_update());
  }


  std::string
  ElasticProblem::describe_change(const VectorType &change) const
  {
    return system.field().describe(change);
  }


  bool
  ElasticProblem::accept_state()
  {
    return system.accept_state();
  }


  void
  ElasticProblem::reject_state()
  {
    system.reject_state();
  }
} // namespace ssc
