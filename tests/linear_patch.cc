// Patch test of the volume discretisations on a distorted (non-affine)
// mesh: a layer whose thickness varies as 2 + 0.3 x + 0.2 y, four cells
// across, with a linear displacement u = A x prescribed on the whole
// boundary. Every formulation must reproduce it exactly (the incompatible
// modes only thanks to Taylor's centre-Jacobian modification).

#include <deal.II/base/function.h>

#include <iostream>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/mesh/background_mesh.h>

#include "quiet_elasticity.h"
#include "tests.h"

using namespace dealii;

class LinearField : public Function<3>
{
public:
  LinearField()
    : Function<3>(3)
  {}
  double
  value(const Point<3> &p, const unsigned int c) const override
  {
    return A[c][0] * p[0] + A[c][1] * p[1] + A[c][2] * p[2];
  }
  Tensor<1, 3>
  gradient(const Point<3> &, const unsigned int c) const override
  {
    return Tensor<1, 3>({A[c][0], A[c][1], A[c][2]});
  }

private:
  static constexpr double A[3][3] = {{0.01, -0.02, 0.015},
                                     {0.005, 0.02, -0.01},
                                     {-0.012, 0.007, 0.03}};
};

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::LayerStack layers;
  layers.add_layer(
    "block", ssc::LayerKind::deep, "2 + 0.3*x + 0.2*y", 1., 0.45, 4);
  const ssc::MeshParameters mesh_parameters = uniform_patch(2, 0.5);
  ssc::BackgroundMesh       mesh(layers, mesh_parameters, MPI_COMM_WORLD);
  mesh.build();
  auto exact = std::make_shared<LinearField>();
  for (const auto formulation : {ssc::Formulation::displacement,
                                 ssc::Formulation::mixed,
                                 ssc::Formulation::enhanced})
    {
      ssc::ElasticityParameters parameters;
      parameters.formulation = formulation;
      const auto [l2, h1] = patch_test_errors(mesh, layers, parameters, exact);
      deallog << ssc::to_string(formulation)
              << ": L2 and H1 errors below 1e-10: "
              << (l2 < 1e-10 && h1 < 1e-10 ? "yes" : "no") << std::endl;
    }
}
