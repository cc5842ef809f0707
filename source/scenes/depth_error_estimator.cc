#include <ssc/scenes/coarser_mesh_depth_estimate.h>
#include <ssc/scenes/depth_error_estimator.h>
#include <ssc/scenes/enriched_depth_estimate.h>

namespace ssc
{
  std::unique_ptr<DepthErrorEstimator>
  DepthErrorEstimator::create(const Parameters &parameters,
                              const MPI_Comm    mpi_communicator)
  {
    switch (parameters.punch.depth_error_estimate)
      {
        case DepthErrorEstimate::none:
          return nullptr;
        case DepthErrorEstimate::enriched_degree:
          return std::make_unique<EnrichedDepthEstimate>(parameters,
                                                         mpi_communicator);
        case DepthErrorEstimate::coarser_mesh:
          return std::make_unique<CoarserMeshDepthEstimate>(parameters,
                                                            mpi_communicator);
      }
    AssertThrow(false, ExcInternalError());
    return nullptr;
  }


  void
  DepthErrorEstimator::prepare(ConditionalOStream &)
  {}
} // namespace ssc
