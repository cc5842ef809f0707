// Coulomb friction on the punch's face between its limits, on the coarse
// forearm indentation at finite strain (0.2 N): with mu = 0 the friction
// carries nothing and the depth is the frictionless punch's; with a large
// mu the skin sticks and the depth approaches the bonded punch's (the
// stick stiffness's elastic slip is all that remains); a skin friction
// coefficient (mu = 0.5) lies between the two, and the more friction, the
// shallower the punch goes.

#include <cmath>
#include <iomanip>

#include "indentation_run.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const auto depth = [](const std::vector<std::string> &extra) {
    return run_indentation("indentation_neo_hookean.prm",
                           {"Punch/Forces=0.2"},
                           extra)
      .depths.back();
  };
  const double bonded = depth({"Punch/Contact=bonded", "Run/Name=bonded"});
  const double frictionless =
    depth({"Punch/Contact=frictionless", "Run/Name=frictionless"});
  std::vector<double> coefficients = {0., 0.2, 0.5, 100.}, depths;
  for (const double mu : coefficients)
    depths.push_back(depth({"Punch/Contact=friction",
                            "Punch/Friction coefficient=" + std::to_string(mu),
                            "Run/Name=friction"}));
  dealii::deallog << std::setprecision(5) << "depth at 0.2 N: bonded " << bonded
                  << " mm, frictionless " << frictionless << " mm" << std::endl;
  bool decreasing = true;
  for (unsigned int k = 0; k < coefficients.size(); ++k)
    {
      dealii::deallog << std::setprecision(3) << "mu = " << coefficients[k]
                      << ": " << std::setprecision(5) << depths[k] << " mm"
                      << std::endl;
      decreasing = decreasing && (k == 0 || depths[k] <= depths[k - 1]);
    }
  dealii::deallog << "mu = 0 is the frictionless punch (relative difference "
                     "below 1e-8): "
                  << (std::abs(depths[0] / frictionless - 1.) < 1e-8 ? "yes" :
                                                                       "no")
                  << std::endl;
  dealii::deallog << "deeper with less friction: "
                  << (decreasing ? "yes" : "no") << std::endl;
  dealii::deallog << "mu = 0.5 between bonded and frictionless: "
                  << (depths[2] >= bonded && depths[2] <= frictionless ? "yes" :
                                                                         "no")
                  << std::endl;
  dealii::deallog << "mu = 100 within 1 % of bonded: "
                  << (std::abs(depths[3] / bonded - 1.) < 0.01 ? "yes" : "no")
                  << std::endl;
}
