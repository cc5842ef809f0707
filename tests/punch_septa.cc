// The bonded punch on a layered block with and without its microstructure
// (septa as embedded membranes of 0.1 MPa, 0.1 mm thick; ligaments as
// cables): the septa and ligaments stiffen the tissue. The .mpirun=2
// variant checks that 1 and 2 ranks agree while septa and ligaments cross
// the partition (the stiffness is printed to 6 digits, the solver tolerance
// is 1e-12).

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
  double      stiffness[4];
  const char *labels[4] = {"layers only",
                           "septa",
                           "ligaments",
                           "septa and ligaments"};
  for (unsigned int k = 0; k < 4; ++k)
    {
      ssc::Parameters parameters;
      parameters.read(SOURCE_DIR "/data/septa_block.prm",
                      {std::string("Microstructure/Lobules=") +
                         (k % 2 == 1 ? "true" : "false"),
                       std::string("Microstructure/Ligaments/Enabled=") +
                         (k >= 2 ? "true" : "false"),
                       "Run/Name=septa_block_" + std::to_string(k)});
      const ssc::IndentationResult result =
        ssc::IndentationScene(parameters, MPI_COMM_WORLD).run();
      stiffness[k] = result.stiffness;
      std::ostringstream line;
      line << std::setw(20) << labels[k] << ": stiffness "
           << std::setprecision(6) << result.stiffness << " N/mm";
      if (k > 0)
        line << ", " << std::fixed << std::setprecision(1)
             << 100 * (result.stiffness / stiffness[0] - 1)
             << " % above layers only";
      dealii::deallog << line.str() << std::endl;
    }
  dealii::deallog << "septa stiffen: "
                  << (stiffness[1] > stiffness[0] ? "yes" : "no")
                  << ", ligaments stiffen: "
                  << (stiffness[2] > stiffness[0] ? "yes" : "no") << std::endl;
}
