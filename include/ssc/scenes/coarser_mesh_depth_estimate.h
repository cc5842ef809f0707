#ifndef ssc_scenes_coarser_mesh_depth_estimate_h
#define ssc_scenes_coarser_mesh_depth_estimate_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

#include <ssc/scenes/companion_model.h>
#include <ssc/scenes/depth_error_estimator.h>
#include <ssc/scenes/parameters.h>

namespace ssc
{
  /**
   * The discretisation error of the punch's depth at each prescribed
   * force, computed by the run from a second solve on the mesh with one
   * global refinement fewer (Punch/Depth error estimate = coarser mesh):
   * the same patch, layers, lobules, septa, ligaments, ties and contact,
   * every cell twice as large. With d_h the scene's depth and d_2h the
   * coarser mesh's, Richardson's estimate of the error of d_h is
   *
   *   e_h = (d_h - d_2h) / (2^p - 1).
   *
   * Why this estimate: at finite strain with contact, the one-step
   * estimates in a richer space meet indefinite tangents (Q1 equilibria
   * are saddles of the richer energy; EnrichedDepthEstimate), whereas a
   * converged solve on a coarser nested mesh is cheap (an eighth of the
   * cells) and needs nothing the scene does not have. Why p = 1.5 and not
   * the observed order: a depth at the singular line where the punch's
   * tie ends converges with an order between 1 (the singularity) and 2
   * (the energy's rate for smooth problems); on three nested meshes the
   * forearm scene shows 1.0-1.44 at 0.35-1.5 N (and 0.43 at 1.8 N, not
   * yet asymptotic). With p = 1.5 the estimate is within a factor
   * 0.55-1.64 of the true error for any order between 1 and 2; the
   * observed order needs a third mesh, which costs 8 times the scene
   * (benchmarks/forearm/depth_error_effectivity.py).
   */
  class CoarserMeshDepthEstimate : public DepthErrorEstimator
  {
  public:
    /// The coarser model of @p parameters (force control, Mesh/Global
    /// refinements >= 1), built on @p mpi_communicator. Where the scene's
    /// preconditioner is the V-cycle and the coarser mesh has no level
    /// below it, its tangents are factorised (ldlt, any number of ranks).
    CoarserMeshDepthEstimate(const Parameters &parameters,
                             const MPI_Comm    mpi_communicator);

    /// Solves the coarser mesh's load path through the scene's forces and
    /// reports each depth on @p pcout (collective). If the path fails, the
    /// forces it did not reach have no estimate.
    void
    prepare(ConditionalOStream &pcout) override;

    /// (@p depth - the coarser depth at step @p step) / (2^p - 1); NaN
    /// where the coarser path did not reach that step.
    double
    error(const ElasticSystem &system,
          const unsigned int   step,
          const double         force,
          const double         depth) override;

    std::string
    method() const override;

    types::global_dof_index
    n_dofs() override;

    /// The convergence order p the estimate assumes (see the class).
    static constexpr double assumed_order = 1.5;

  private:
    CompanionModel      coarser;
    std::vector<double> depths;
    /// Why the coarser path stopped (empty if it reached every force).
    std::string path_failure;
  };
} // namespace ssc

#endif
