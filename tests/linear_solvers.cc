// The linear solvers give the same answer: the coarse layered punch of
// punch_small.prm solved by CG with AMG, by the displacement-pressure block
// solver (Linear solver/Method = block) and by the sparse direct solver
// (MUMPS) has the same stiffness to a relative 1e-7, for the mixed Q1, the
// enhanced Q1 and the mixed Q2 formulations, at nu = 0.3 and (block and
// direct only: CG does not converge there) nu = 0.4999 in every layer; and
// so has a finite-strain (neo-Hookean) punch pressed 0.5 mm. Iteration
// counts belong to benchmarks/, not here.

#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include <ssc/parameters.h>
#include <ssc/scenes/indentation_scene.h>

#include "tests.h"

namespace
{
  double
  stiffness(const std::vector<std::string> &settings,
            const std::string              &method,
            const std::string              &name)
  {
    std::vector<std::string> overrides = {
      "Elasticity/Linear solver/Method=" + method,
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
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::map<std::string, std::vector<std::string>> discretisations = {
    {"mixed Q1", {"Elasticity/Formulation=mixed"}},
    {"enhanced Q1", {"Elasticity/Formulation=enhanced"}},
    {"mixed Q2",
     {"Elasticity/Formulation=mixed",
      "Elasticity/Degree=2",
      "Mesh/Region of interest/Local refinements=0"}}};
  for (const auto &[label, settings] : discretisations)
    for (const std::string nu : {"0.3", "0.4999"})
      {
        std::vector<std::string> case_settings = settings;
        for (const std::string layer : {"skin", "fat", "muscle"})
          case_settings.push_back("Layer stack/" + layer +
                                  "/Poisson's ratio=" + nu);
        const double direct = stiffness(case_settings, "direct", "direct");
        const double block  = stiffness(case_settings, "block", "block");
        bool         agree  = std::abs(block / direct - 1) < 1e-7;
        if (nu == "0.3")
          agree =
            agree &&
            std::abs(stiffness(case_settings, "cg", "cg") / direct - 1) < 1e-7;
        std::ostringstream line;
        line << label << ", nu = " << nu << ": stiffness "
             << std::setprecision(6) << direct
             << " N/mm, the solvers agree to 1e-7: " << (agree ? "yes" : "no");
        dealii::deallog << line.str() << std::endl;
      }

  std::vector<std::string> finite = {"Punch/Depth=0.5", "Punch/Load steps=2"};
  for (const std::string layer : {"skin", "fat", "muscle"})
    finite.push_back("Layer stack/" + layer + "/Material model=neo-Hookean");
  const double       direct = stiffness(finite, "direct", "finite_direct");
  const double       block  = stiffness(finite, "block", "finite_block");
  const double       cg     = stiffness(finite, "cg", "finite_cg");
  std::ostringstream line;
  line << "neo-Hookean, 0.5 mm: force/depth " << std::setprecision(6) << direct
       << " N/mm, the solvers agree to 1e-7: "
       << (std::abs(block / direct - 1) < 1e-7 &&
               std::abs(cg / direct - 1) < 1e-7 ?
             "yes" :
             "no");
  dealii::deallog << line.str() << std::endl;
}
