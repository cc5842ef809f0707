// Manufactured solution, nu = 0.3: optimal rates (L2 p+1, H1 p) for Q1 and
// Q2 on one layer and on a three-layer stack with 20:1 stiffness contrast.

#include "mms_driver.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using namespace ssc_test;

  ssc::LayerStack one_layer;
  one_layer.add_layer("block", ssc::LayerKind::deep, "1", 1., 0.3, 2);
  auto plain = std::make_shared<LayeredTrigField>(std::vector<double>{});

  ssc::LayerStack three_layers;
  three_layers.add_layer("skin", ssc::LayerKind::skin, "1/3", 20., 0.3, 1);
  three_layers.add_layer("fat", ssc::LayerKind::SAT, "1/3", 1., 0.3, 1);
  three_layers.add_layer("muscle", ssc::LayerKind::deep, "1/3", 5., 0.3, 1);
  auto layered =
    std::make_shared<LayeredTrigField>(std::vector<double>{-1. / 3, -2. / 3});

  convergence_study("one layer, Q1",
                    one_layer,
                    plain,
                    0.3,
                    1,
                    ssc::Formulation::displacement,
                    5);
  convergence_study("one layer, Q2",
                    one_layer,
                    plain,
                    0.3,
                    2,
                    ssc::Formulation::displacement,
                    4);
  convergence_study("three layers 20:1:5, Q1",
                    three_layers,
                    layered,
                    0.3,
                    1,
                    ssc::Formulation::displacement,
                    4);
  convergence_study("three layers 20:1:5, Q1 enhanced (incompatible modes)",
                    three_layers,
                    layered,
                    0.3,
                    1,
                    ssc::Formulation::enhanced,
                    4);
  convergence_study("three layers 20:1:5, Q2",
                    three_layers,
                    layered,
                    0.3,
                    2,
                    ssc::Formulation::displacement,
                    3);
}
