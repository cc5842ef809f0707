// Force-controlled and displacement-controlled punches agree: the depth
// computed for a prescribed force (vertical displacements under the punch
// tied to one master unknown) gives back that force when it is prescribed,
// for the bonded and the frictionless punch, with septa and ligaments
// embedded. The tied punch carries exactly the applied force (reaction from
// the residual).

#include <cmath>
#include <iomanip>
#include <sstream>

#include "indentation_run.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const std::string contact : {"bonded", "frictionless"})
    {
      const auto run = [&](const std::vector<std::string> &extra) {
        return run_indentation("data/septa_block.prm",
                               {"Punch/Contact=" + contact},
                               extra);
      };
      const auto         by_force = run({"Punch/Control=force",
                                         "Punch/Forces=0.02, 0.05",
                                         "Microstructure/Lobules=true",
                                         "Microstructure/Ligaments/Enabled=true",
                                         "Run/Name=force_" + contact});
      std::ostringstream depth;
      depth << std::setprecision(17) << by_force.depths.back();
      const auto         by_depth = run({"Punch/Control=displacement",
                                         "Punch/Depth=" + depth.str(),
                                         "Microstructure/Lobules=true",
                                         "Microstructure/Ligaments/Enabled=true",
                                         "Run/Name=depth_" + contact});
      std::ostringstream line;
      line << contact << ": 0.05 N gives " << std::setprecision(6)
           << by_force.depths.back() << " mm; that depth needs "
           << by_depth.forces.back() << " N; relative difference below 1e-8: "
           << (std::abs(by_depth.forces.back() / 0.05 - 1) < 1e-8 ? "yes" :
                                                                    "no");
      dealii::deallog << line.str() << std::endl;
    }
}
