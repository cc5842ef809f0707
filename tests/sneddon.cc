// Frictionless rigid flat punch on a deep homogeneous block against
// Sneddon's half-space stiffness F/delta = 2 a E / (1 - nu^2), through the
// punch scene and benchmarks/punch_sneddon/. The frictionless punch
// imposes only u_z = -delta under the punch and leaves the surface free to
// slide, which is exactly Sneddon's mixed boundary-value problem (a bonded
// punch would be stiffer by (1 - nu) ln(3 - 4 nu) / (1 - 2 nu), 2.9 % at
// nu = 0.3). Levels refine towards the punch edge, whose circle the mesh
// lines follow exactly; the discrete stiffness then converges from above
// (conforming displacement FE under displacement control), like the fixed
// bottom of the finite block, which adds about +0.2 %.

#include <cmath>
#include <iomanip>
#include <sstream>

#include <ssc/scenes/indentation_scene.h>
#include <ssc/scenes/parameters.h>

#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  double error = 0;
  for (const unsigned int level : {10u, 11u, 12u})
    {
      ssc::Parameters parameters;
      parameters.read(SOURCE_DIR
                      "/../benchmarks/punch_sneddon/punch_sneddon.prm",
                      {"Run/Output directory=results",
                       "Run/Test mode=true",
                       "Mesh/Region of interest/Local refinements=" +
                         std::to_string(level)});
      const ssc::IndentationResult result =
        ssc::IndentationScene(parameters, MPI_COMM_WORLD).run();
      error = result.stiffness / result.half_space_stiffness - 1.;
      std::ostringstream line;
      line << "edge refinements " << level << " dofs " << result.dofs
           << std::setprecision(5) << " stiffness " << result.stiffness
           << " N/mm, Sneddon " << result.half_space_stiffness
           << " N/mm, error " << std::fixed << std::setprecision(2)
           << 100 * error << " %";
      dealii::deallog << line.str() << std::endl;
    }
  dealii::deallog << "finest level within 1 % of Sneddon: "
                  << (std::abs(error) < 0.01 ? "yes" : "no") << std::endl;
}
