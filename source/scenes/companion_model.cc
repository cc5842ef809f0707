#include <ssc/scenes/companion_model.h>

namespace ssc
{
  namespace
  {
    /// @p parameters after reading @p scene's file with its overrides,
    /// then @p overrides, then no fields and no estimate (a Parameters
    /// object is neither copied nor moved, so it is filled in place).
    const Parameters &
    read_companion(Parameters                     &parameters,
                   const Parameters               &scene,
                   const std::vector<std::string> &overrides)
    {
      std::vector<std::string> all = scene.overrides();
      all.insert(all.end(), overrides.begin(), overrides.end());
      all.emplace_back("Run/Write fields=false");
      all.emplace_back("Punch/Depth error estimate=none");
      parameters.read(scene.file(), all);
      return parameters;
    }
  } // namespace


  CompanionModel::CompanionModel(const Parameters               &scene,
                                 const std::vector<std::string> &overrides,
                                 const MPI_Comm mpi_communicator)
    : silent(std::cout, false)
    , timer(mpi_communicator,
            silent,
            TimerOutput::never,
            TimerOutput::wall_times)
    , model(read_companion(companion_parameters, scene, overrides),
            mpi_communicator,
            timer,
            silent,
            silent)
    , punch_loading(companion_parameters, model.system(), timer, silent)
  {}
} // namespace ssc
