// The sparse Cholesky preconditioner (Elasticity/Linear solver/
// Preconditioner = cholesky) gives the answer of the sparse direct solver
// (MUMPS): the coarse layered punch of punch_small.prm, linear, with CG and
// with the displacement-pressure block solver, for the mixed Q1, enhanced
// Q1 and mixed Q2 formulations at nu = 0.3 and 0.4999, to a relative 1e-7;
// and a finite-strain (neo-Hookean) punch in four load steps, where the
// factor of an earlier tangent is reused across Newton iterations: once with
// a generous reuse limit (the factor kept), once with a limit of one
// iteration (every reuse stopped, the tangent refactorised, the solve
// continued). On two ranks the preconditioner is refused with a clear error
// (it factorises the whole matrix on one process).

#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include "punch_solver_cases.h"
#include "tests.h"

namespace
{
  std::vector<std::string>
  with(std::vector<std::string> settings, const std::vector<std::string> &more)
  {
    settings.insert(settings.end(), more.begin(), more.end());
    return settings;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string cholesky =
    "Elasticity/Linear solver/Preconditioner=cholesky";
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    {
      std::string message;
      try
        {
          punch_stiffness({cholesky}, "refused");
        }
      catch (const std::exception &e)
        {
          message = e.what();
        }
      dealii::deallog << "refused on several ranks, naming the parameter: "
                      << (message.find("Preconditioner = cholesky") !=
                              std::string::npos ?
                            "yes" :
                            "no")
                      << std::endl;
      return 0;
    }

  for (const auto &[label, case_settings] : punch_solver_cases())
    {
      const double direct =
        punch_stiffness(with(case_settings,
                             {"Elasticity/Linear solver/Method=direct"}),
                        "direct");
      const double cg = punch_stiffness(with(case_settings, {cholesky}), "cg");
      const double block =
        punch_stiffness(with(case_settings,
                             {cholesky,
                              "Elasticity/Linear solver/Method=block"}),
                        "block");
      std::ostringstream line;
      line << label << ": stiffness " << std::setprecision(6) << direct
           << " N/mm, cg and block with the Cholesky factor agree with "
              "the direct solver to 1e-7: "
           << (std::abs(cg / direct - 1) < 1e-7 &&
                   std::abs(block / direct - 1) < 1e-7 ?
                 "yes" :
                 "no");
      dealii::deallog << line.str() << std::endl;
    }

  std::vector<std::string> finite = {"Punch/Depth=0.5", "Punch/Load steps=4"};
  for (const std::string layer : {"skin", "fat", "muscle"})
    finite.push_back("Layer stack/" + layer + "/Material model=neo-Hookean");
  const double direct =
    punch_stiffness(with(finite, {"Elasticity/Linear solver/Method=direct"}),
                    "finite_direct");
  for (const std::string limit : {"1000", "1"})
    {
      const double reused =
        punch_stiffness(with(finite,
                             {cholesky,
                              "Elasticity/Linear solver/Refactorization "
                              "iterations=" +
                                limit}),
                        "finite_cholesky_" + limit);
      std::ostringstream line;
      line << "neo-Hookean, 0.5 mm, reuse limit " << limit
           << " iterations: force/depth " << std::setprecision(6) << direct
           << " N/mm, agrees with the direct solver to 1e-7: "
           << (std::abs(reused / direct - 1) < 1e-7 ? "yes" : "no");
      dealii::deallog << line.str() << std::endl;
    }
}
