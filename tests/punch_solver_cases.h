#ifndef ssc_tests_punch_solver_cases_h
#define ssc_tests_punch_solver_cases_h

// The cases on which the solver tests compare linear solvers: the coarse
// layered punch of punch_small.prm, solved tightly, in three
// discretisations at nu = 0.3 and 0.4999 in every layer.

#include <map>
#include <string>
#include <vector>

#include <ssc/scenes/indentation_scene.h>
#include <ssc/scenes/parameters.h>

/// Force over depth of the punch of punch_small.prm with @p settings
/// (run folder @p name), the solvers at tight tolerances.
inline double
punch_stiffness(const std::vector<std::string> &settings,
                const std::string              &name)
{
  std::vector<std::string> overrides = {
    "Elasticity/Linear solver/Tolerance=1e-12",
    "Elasticity/Linear solver/Max iterations=5000",
    "Punch/Profile length=0",
    "Punch/Section=false",
    "Run/Write fields=false",
    "Nonlinear solver/Relative tolerance=1e-10",
    "Run/Name=" + name};
  overrides.insert(overrides.end(), settings.begin(), settings.end());
  ssc::Parameters parameters;
  parameters.read(SOURCE_DIR "/punch_small.prm", overrides);
  const ssc::IndentationResult result =
    ssc::IndentationScene(parameters, MPI_COMM_WORLD).run();
  return result.forces.back() / result.depths.back();
}


/// The mixed Q1, enhanced Q1 and mixed Q2 discretisations, each at nu =
/// 0.3 and 0.4999 in every layer: label -> settings.
inline std::vector<std::pair<std::string, std::vector<std::string>>>
punch_solver_cases()
{
  const std::map<std::string, std::vector<std::string>> discretisations = {
    {"mixed Q1", {"Elasticity/Formulation=mixed"}},
    {"enhanced Q1", {"Elasticity/Formulation=enhanced"}},
    {"mixed Q2",
     {"Elasticity/Formulation=mixed",
      "Elasticity/Degree=2",
      "Mesh/Region of interest/Local refinements=0"}}};
  std::vector<std::pair<std::string, std::vector<std::string>>> cases;
  for (const auto &[label, settings] : discretisations)
    for (const std::string nu : {"0.3", "0.4999"})
      {
        std::vector<std::string> case_settings = settings;
        for (const std::string layer : {"skin", "fat", "muscle"})
          case_settings.push_back("Layer stack/" + layer +
                                  "/Poisson's ratio=" + nu);
        cases.emplace_back(label + ", nu = " + nu, case_settings);
      }
  return cases;
}

#endif
