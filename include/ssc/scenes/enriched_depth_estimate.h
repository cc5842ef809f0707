#ifndef ssc_scenes_enriched_depth_estimate_h
#define ssc_scenes_enriched_depth_estimate_h

#include <deal.II/lac/full_matrix.h>

#include <string>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/scenes/companion_model.h>
#include <ssc/scenes/depth_error_estimator.h>
#include <ssc/scenes/parameters.h>

namespace ssc
{
  /**
   * The discretisation error of the punch's depth at a given force,
   * computed by the run (Punch/Depth error estimate = enriched degree):
   * one Newton step of the next richer discretisation, Q2 with the cell's
   * mean dilatation (Q2-P0), on the same mesh, lobules, septa, ligaments,
   * ties and contact, from the scene's converged Q1 state interpolated
   * into it.
   *
   * Why this estimate: the goal is a functional of the state (the depth at
   * the prescribed force, the tie's master dof), and the dual-weighted
   * residual estimate of a goal with the adjoint solved in the richer
   * space, z = K_+^{-T} J', is J(u_+) - J(u_h) ~ z . (-r_+(u_h)) =
   * J(K_+^{-1} (-r_+(u_h))): the goal's change in one Newton step of the
   * richer discretisation from the scene's state. It needs no adjoint
   * code, has the contact and the embedded terms inside r_+ and K_+, and
   * costs one assembly and one solve per force on the richer system. For
   * a linear problem it is exact: the richer depth minus the scene's.
   * Q2-P0 and not Q2-P1: with P0 the richer spaces contain the scene's
   * (Q1-P0), whereas a P1 dilatation would at once give bulk energy to
   * the variation of J within the cells that Q1-P0 leaves free.
   *
   * Where the richer tangent at the scene's state is indefinite, the step
   * follows negative curvature and estimates nothing: depth_change() then
   * returns NaN. At finite strain this is what the forearm scene meets:
   * about 100 negative eigenvalues of the Q2-P0 tangent at its converged
   * Q1 states (modes that Q1 cannot represent), so its error needs a
   * converged richer solve instead.
   */
  class EnrichedDepthEstimate : public DepthErrorEstimator
  {
  public:
    /// The richer model of the scene of @p parameters (Elasticity/Degree
    /// 1, force control), built quietly on @p mpi_communicator.
    EnrichedDepthEstimate(const Parameters &parameters,
                          const MPI_Comm    mpi_communicator);

    /// The depth (mm) of the richer discretisation minus that of @p system
    /// at the force @p force (N) that @p system's converged state carries,
    /// to first order; NaN where the richer tangent is indefinite or its
    /// solve fails (collective).
    double
    error(const ElasticSystem &system,
          const unsigned int   step,
          const double         force,
          const double         depth) override;

    std::string
    method() const override;

    types::global_dof_index
    n_dofs() override;

  private:
    /// Sets the richer field to @p system's displacement, interpolated
    /// (exactly: Q1 lies in Q2) cell by cell: both meshes are built from
    /// the same parameters, so their active cells match one to one.
    void
    interpolate_state(const ElasticSystem &system);

    CompanionModel enriched;
    /// Q1 cell values to Q2 cell values (vector-valued elements).
    FullMatrix<double> interpolation;
  };
} // namespace ssc

#endif
