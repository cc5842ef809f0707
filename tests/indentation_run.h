#ifndef ssc_tests_indentation_run_h
#define ssc_tests_indentation_run_h

#include <string>
#include <vector>

#include <ssc/scenes/indentation_scene.h>
#include <ssc/scenes/parameters.h>

/// The indentation scene of tests/@p prm with the parameter overrides
/// @p base and then @p extra ("Section/Name=value"), on MPI_COMM_WORLD,
/// without the surface profile and the section: the tests compare depths
/// and forces.
inline ssc::IndentationResult
run_indentation(const std::string              &prm,
                const std::vector<std::string> &base,
                const std::vector<std::string> &extra)
{
  ssc::Parameters          parameters;
  std::vector<std::string> overrides = {"Punch/Profile length=0",
                                        "Punch/Section=false"};
  overrides.insert(overrides.end(), base.begin(), base.end());
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  parameters.read(std::string(SOURCE_DIR) + "/" + prm, overrides);
  return ssc::IndentationScene(parameters, MPI_COMM_WORLD).run();
}

#endif
