// Small loads reproduce the linear results: the coarse layered punch of
// punch_small.prm pressed 1e-6 mm with every layer neo-Hookean or
// corotational (Newton's method, load steps) gives the stiffness of the
// linear model to a relative 1e-6, in the displacement and in the mixed
// formulation (whose small-strain limit, the mean dilatation, is the linear
// B-bar).

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
  for (const std::string formulation : {"displacement", "mixed"})
    {
      double stiffness[3];
      for (const unsigned int model : {0u, 1u, 2u})
        {
          std::vector<std::string> overrides = {
            "Elasticity/Formulation=" + formulation,
            "Punch/Depth=1e-6",
            "Punch/Load steps=1",
            "Punch/Profile length=0",
            "Punch/Section=false",
            "Run/Write fields=false",
            "Nonlinear solver/Relative tolerance=1e-8",
            "Nonlinear solver/Absolute tolerance=1e-14",
            "Run/Name=small_" + formulation + std::to_string(model)};
          if (model > 0)
            for (const std::string layer : {"skin", "fat", "muscle"})
              overrides.push_back(
                "Layer stack/" + layer + "/Material model=" +
                (model == 1 ? "neo-Hookean" : "corotational"));
          ssc::Parameters parameters;
          parameters.read(SOURCE_DIR "/punch_small.prm", overrides);
          stiffness[model] =
            ssc::IndentationScene(parameters, MPI_COMM_WORLD).run().stiffness;
        }
      std::ostringstream line;
      line << formulation << ": linear " << std::setprecision(6) << stiffness[0]
           << " N/mm, neo-Hookean " << stiffness[1] << " N/mm, corotational "
           << stiffness[2] << " N/mm, relative differences below 1e-6: "
           << (std::abs(stiffness[1] / stiffness[0] - 1) < 1e-6 &&
                   std::abs(stiffness[2] / stiffness[0] - 1) < 1e-6 ?
                 "yes" :
                 "no");
      dealii::deallog << line.str() << std::endl;
    }
}
