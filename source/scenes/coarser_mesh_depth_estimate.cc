#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include <ssc/base/user_message.h>
#include <ssc/scenes/coarser_mesh_depth_estimate.h>
#include <ssc/scenes/quasi_static_driver.h>

namespace ssc
{
  namespace
  {
    /// The scene's mesh with one global refinement fewer, and a solver
    /// that works on it.
    std::vector<std::string>
    coarser_overrides(const Parameters &parameters)
    {
      const unsigned int refinements = parameters.mesh.global_refinements;
      // Parameters::check_formulation() refuses a scene without a level
      Assert(refinements >= 1, ExcInternalError());
      std::vector<std::string> overrides = {"Mesh/Global refinements=" +
                                            std::to_string(refinements - 1)};
      // the V-cycle needs a level below the mesh; a factor works on any
      // number of ranks and at this size costs little
      if (refinements == 1 &&
          parameters.elasticity.linear_solver.preconditioner ==
            DisplacementPreconditioner::gmg)
        overrides.emplace_back("Elasticity/Linear solver/Preconditioner=ldlt");
      return overrides;
    }
  } // namespace


  CoarserMeshDepthEstimate::CoarserMeshDepthEstimate(
    const Parameters &parameters,
    const MPI_Comm    mpi_communicator)
    : coarser(parameters, coarser_overrides(parameters), mpi_communicator)
  {}


  void
  CoarserMeshDepthEstimate::prepare(ConditionalOStream &pcout)
  {
    const Parameters         &parameters = coarser.parameters();
    const std::vector<double> loads      = parameters.punch.loads();
    PunchLoading             &loading    = coarser.loading();
    QuasiStaticDriver         driver(coarser.system(),
                             parameters.newton,
                             coarser.silent_stream(),
                             false);
    depths.clear();
    path_failure.clear();
    try
      {
        follow_punch_path(
          driver, loading, parameters, [&](const unsigned int step) {
            depths.push_back(loading.depth(loads[step]));
            pcout << "  coarser mesh: force " << std::setprecision(6)
                  << loads[step] << " N, depth " << depths.back() << " mm";
            if (!parameters.run.test_mode)
              pcout << " (" << driver.statistics().back().newton_iterations
                    << " Newton iterations)";
            pcout << std::endl;
          });
      }
    catch (const ExceptionBase &error)
      {
        // the estimate's path is not the scene's: the scene goes on
        path_failure =
          "the coarser mesh's path stopped: " + user_message(error);
        pcout << "  " << path_failure << std::endl;
      }
  }


  double
  CoarserMeshDepthEstimate::error(const ElasticSystem &,
                                  const unsigned int step,
                                  const double,
                                  const double depth)
  {
    failure.clear();
    if (step >= depths.size())
      {
        failure = path_failure;
        return std::numeric_limits<double>::quiet_NaN();
      }
    return (depth - depths[step]) / (std::pow(2., assumed_order) - 1.);
  }


  std::string
  CoarserMeshDepthEstimate::method() const
  {
    std::ostringstream text;
    text << "Richardson from this mesh and the mesh with one refinement "
            "fewer, assumed order "
         << assumed_order;
    return text.str();
  }


  types::global_dof_index
  CoarserMeshDepthEstimate::n_dofs()
  {
    return coarser.system().field().dof_handler().n_dofs();
  }
} // namespace ssc
