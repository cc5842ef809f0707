// Manufactured divergence-free solution at nu = 0.4999: the mixed (B-bar,
// Q_p-P_{p-1}^disc) formulation keeps optimal rates for Q1 and Q2; plain Q1
// is shown for contrast (locking: large errors, rates far from optimal on
// these meshes).

#include "mms_driver.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using namespace ssc_test;

  ssc::LayerStack block;
  block.add_layer("block", ssc::LayerKind::deep, "1", 1., 0.4999, 2);
  auto field = std::make_shared<DivergenceFreeField>();

  convergence_study("nu = 0.4999, Q1 displacement (locks)",
                    block,
                    field,
                    0.4999,
                    1,
                    ssc::Formulation::displacement,
                    4);
  convergence_study("nu = 0.4999, Q1 mixed",
                    block,
                    field,
                    0.4999,
                    1,
                    ssc::Formulation::mixed,
                    4);
  convergence_study("nu = 0.4999, Q1 enhanced",
                    block,
                    field,
                    0.4999,
                    1,
                    ssc::Formulation::enhanced,
                    4);
  convergence_study("nu = 0.4999, Q2 mixed",
                    block,
                    field,
                    0.4999,
                    2,
                    ssc::Formulation::mixed,
                    3);
}
