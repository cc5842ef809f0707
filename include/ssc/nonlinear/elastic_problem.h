#ifndef ssc_nonlinear_elastic_problem_h
#define ssc_nonlinear_elastic_problem_h

#include <ssc/mechanics/elastic_system.h>
#include <ssc/nonlinear/nonlinear_problem.h>

namespace ssc
{
  /**
   * The mechanics (ElasticSystem) as Newton's method sees it: the state is
   * the displacement, the update that of the last linear solve, the
   * constraint gap that of the prescribed displacements.
   */
  class ElasticProblem : public NonlinearProblem
  {
  public:
    explicit ElasticProblem(ElasticSystem &system);

    double
    residual() override;

    double
    tangent() override;

    double
    rhs_norm() const override;

    LinearSolveReport
    solve_update(const SolveTarget &target) override;

    TruncatedCGReport
    solve_update_within(const double       radius,
                        const SolveTarget &target,
                        const bool         new_tangent) override;

    void
    shift_tangent(const double shift) override;

    double
    update_curvature() const override;

    double
    slope_along_update() const override;

    void
    store_state() override;

    void
    set_state_from_stored(const double step) override;

    void
    restore_state() override;

    VectorType
    state() const override;

    void
    set_state(const VectorType &state) override;

    double
    constraint_gap() const override;

    double
    applied_load() const override;

    std::string
    describe_update() const override;

    std::string
    describe_change(const VectorType &change) const override;

    bool
    accept_state() override;

    void
    reject_state() override;

  private:
    /// The last update with its constrained entries zeroed.
    VectorType
    free_update() const;

    ElasticSystem &system;
    VectorType     stored_state;
  };
} // namespace ssc

#endif
