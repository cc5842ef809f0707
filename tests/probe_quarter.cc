// The quarter model (Mesh/Symmetry = quarter) of a rectangular probe on
// three layers, on a box mesh graded towards the probe's edges (Mesh/Core
// edge cell size): the same force, depth and layer strains under the
// centre as the whole patch, under displacement and force control, in the
// displacement and the mixed formulation, to a relative 1e-8; the quarter
// has a quarter of the cells. (The .mpirun=2 variant: the same on 2 ranks.)

#include <cmath>
#include <iomanip>
#include <sstream>

#include <ssc/scenes/indentation_scene.h>
#include <ssc/scenes/parameters.h>

#include "tests.h"

namespace
{
  double
  relative_difference(const ssc::IndentationResult &a,
                      const ssc::IndentationResult &b)
  {
    double largest = std::max(std::abs(a.forces.back() / b.forces.back() - 1),
                              std::abs(a.depths.back() / b.depths.back() - 1));
    for (unsigned int l = 0; l < a.layer_strains.back().size(); ++l)
      largest =
        std::max(largest,
                 std::abs(
                   a.layer_strains.back()[l] / b.layer_strains.back()[l] - 1));
    return largest;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const std::string formulation : {"displacement", "mixed"})
    for (const std::string control : {"displacement", "force"})
      {
        ssc::IndentationResult result[2];
        for (const unsigned int quarter : {0u, 1u})
          {
            ssc::Parameters parameters;
            parameters.read(SOURCE_DIR "/probe_confined.prm",
                            {"Run/Name=probe_quarter",
                             "Elasticity/Formulation=" + formulation,
                             "Elasticity/Sides=fixed",
                             "Mesh/Patch length x=16",
                             "Mesh/Patch length y=12",
                             "Mesh/Cell size=1.5",
                             "Mesh/Core half width=3",
                             "Mesh/Core half width y=2",
                             "Mesh/Grading ratio=1.5",
                             "Mesh/Core edge cell size=0.5",
                             "Mesh/Symmetry=" +
                               std::string(quarter ? "quarter" : "none"),
                             "Punch/Length=6",
                             "Punch/Width=4",
                             "Punch/Contact=bonded",
                             "Punch/Control=" + control,
                             "Punch/Depth=0.1",
                             "Punch/Forces=0.02"});
            result[quarter] =
              ssc::IndentationScene(parameters, MPI_COMM_WORLD).run();
          }
        std::ostringstream line;
        line << formulation << " formulation, " << control << " control: DoFs "
             << result[0].dofs << " / " << result[1].dofs << ", force "
             << std::setprecision(6) << result[0].forces.back() << " N, depth "
             << result[0].depths.back() << " mm, quarter equals whole to 1e-8: "
             << (relative_difference(result[0], result[1]) < 1e-8 ? "yes" :
                                                                    "no");
        dealii::deallog << line.str() << std::endl;
      }
}
