// The linear solvers give the same answer: the coarse layered punch of
// punch_small.prm solved by CG with AMG, by the displacement-pressure block
// solver (Linear solver/Method = block) and by the sparse direct solver
// (MUMPS) has the same stiffness to a relative 1e-7, for the mixed Q1, the
// enhanced Q1 and the mixed Q2 formulations, at nu = 0.3 and (block, direct
// and CG with the L D L^T factor distributed over the ranks only: CG with
// AMG does not converge there) nu = 0.4999 in every layer; and so has a
// finite-strain (neo-Hookean) punch pressed 0.5 mm. Iteration counts belong
// to benchmarks/, not here.

#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include "punch_solver_cases.h"
#include "tests.h"

namespace
{
  double
  stiffness(std::vector<std::string> settings,
            const std::string       &method,
            const std::string       &name)
  {
    settings.push_back("Elasticity/Linear solver/Method=" + method);
    return punch_stiffness(settings, name);
  }

  /// CG preconditioned by the distributed L D L^T factor
  double
  ldlt_stiffness(std::vector<std::string> settings, const std::string &name)
  {
    settings.push_back("Elasticity/Linear solver/Preconditioner=ldlt");
    return stiffness(settings, "cg", name);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const auto &[label, case_settings] : punch_solver_cases())
    {
      const double direct = stiffness(case_settings, "direct", "direct");
      const double block  = stiffness(case_settings, "block", "block");
      const double ldlt   = ldlt_stiffness(case_settings, "ldlt");
      bool         agree  = std::abs(block / direct - 1) < 1e-7 &&
                   std::abs(ldlt / direct - 1) < 1e-7;
      if (label.find("nu = 0.3") != std::string::npos)
        agree =
          agree &&
          std::abs(stiffness(case_settings, "cg", "cg") / direct - 1) < 1e-7;
      std::ostringstream line;
      line << label << ": stiffness " << std::setprecision(6) << direct
           << " N/mm, the solvers agree to 1e-7: " << (agree ? "yes" : "no");
      dealii::deallog << line.str() << std::endl;
    }

  std::vector<std::string> finite = {"Punch/Depth=0.5", "Punch/Load steps=2"};
  for (const std::string layer : {"skin", "fat", "muscle"})
    finite.push_back("Layer stack/" + layer + "/Material model=neo-Hookean");
  const double       direct = stiffness(finite, "direct", "finite_direct");
  const double       block  = stiffness(finite, "block", "finite_block");
  const double       cg     = stiffness(finite, "cg", "finite_cg");
  const double       ldlt   = ldlt_stiffness(finite, "finite_ldlt");
  std::ostringstream line;
  line << "neo-Hookean, 0.5 mm: force/depth " << std::setprecision(6) << direct
       << " N/mm, the solvers agree to 1e-7: "
       << (std::abs(block / direct - 1) < 1e-7 &&
               std::abs(cg / direct - 1) < 1e-7 &&
               std::abs(ldlt / direct - 1) < 1e-7 ?
             "yes" :
             "no");
  dealii::deallog << line.str() << std::endl;
}
