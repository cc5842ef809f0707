// Mesh/Layout = o-grid: the lateral rings around the circle r = a. On a
// rectangular and on a circular patch, once refined: the cell count is the
// estimate, the volume is the stack's, the top vertices on r = a are twice
// the cells around (refinement keeps new vertices on the circle), the outer
// circle stays a circle, the boundary ids lie on their sides, the depth
// grading follows the edge cell size, and a linear displacement is
// reproduced exactly by Q1 and Q2 on the unrefined mesh (the mesh is valid
// and conforming).

#include <deal.II/base/function.h>

#include <deal.II/grid/grid_tools.h>

#include <cmath>

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
    return 0.01 * (c + 1) * p[0] - 0.02 * p[1] + 0.015 * c * p[2];
  }
  Tensor<1, 3>
  gradient(const Point<3> &, const unsigned int c) const override
  {
    return Tensor<1, 3>({0.01 * (c + 1), -0.02, 0.015 * c});
  }
};

ssc::MeshParameters
o_grid(const ssc::OuterBoundary outer, const unsigned int refinements)
{
  ssc::MeshParameters parameters;
  parameters.layout         = ssc::MeshLayout::o_grid;
  parameters.patch_length_x = 20;
  parameters.patch_length_y = outer == ssc::OuterBoundary::circle ? 20 : 16;
  parameters.fitted_circle_radius  = 2;
  parameters.o_grid_cells_around   = 16;
  parameters.o_grid_edge_cell_size = 0.3;
  parameters.o_grid_radial_grading = 1.4;
  parameters.o_grid_outer_boundary = outer;
  parameters.global_refinements    = refinements;
  parameters.check();
  return parameters;
}

void
check_mesh(const ssc::LayerStack &layers, const ssc::OuterBoundary outer)
{
  const ssc::MeshParameters parameters = o_grid(outer, 1);
  ssc::BackgroundMesh       mesh(layers, parameters, MPI_COMM_WORLD);
  mesh.build();
  const auto  &tria = mesh.triangulation();
  const double a    = parameters.fitted_circle_radius,
               R    = parameters.patch_length_x / 2;
  deallog << ssc::to_string(outer) << " patch: " << tria.n_active_cells()
          << " cells, as estimated: "
          << (tria.n_active_cells() ==
              ssc::BackgroundMesh::estimated_cells(layers, parameters))
          << std::endl;

  // the layers are 1 and 3 + 0.05 x thick: the mean thickness is 4
  const unsigned int n    = 2 * parameters.o_grid_cells_around; // refined once
  const double       area = outer == ssc::OuterBoundary::square ?
                              parameters.patch_length_x * parameters.patch_length_y :
                              0.5 * n * R * R * std::sin(2 * numbers::PI / n);
  deallog << "volume / (4 x lateral area) - 1 below 1e-3: "
          << (std::abs(GridTools::volume(tria) / (4 * area) - 1) < 1e-3)
          << std::endl;

  unsigned int on_edge = 0, on_outer_circle = 0, misplaced = 0;
  for (const Point<3> &p : tria.get_vertices())
    {
      const double r = std::hypot(p[0], p[1]);
      on_edge += std::abs(p[2]) < 1e-12 && std::abs(r - a) < 1e-10;
      on_outer_circle += std::abs(p[2]) < 1e-12 && std::abs(r - R) < 1e-10;
    }
  std::map<types::boundary_id, unsigned int> faces;
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
      {
        ++faces[face->boundary_id()];
        for (const unsigned int v : face->vertex_indices())
          {
            const Point<3> &p = face->vertex(v);
            const double    x = p[0] / (parameters.patch_length_x / 2),
                         y    = p[1] / (parameters.patch_length_y / 2);
            switch (face->boundary_id())
              {
                case ssc::BoundaryId::top:
                  misplaced += std::abs(p[2]) > 1e-12;
                  break;
                case ssc::BoundaryId::bottom:
                  misplaced += std::abs(p[2] + 4 + 0.05 * p[0]) > 1e-10;
                  break;
                case ssc::BoundaryId::x_max:
                  misplaced +=
                    outer == ssc::OuterBoundary::square ?
                      std::abs(x - 1) > 1e-12 :
                      (x < 0.5 || std::hypot(p[0], p[1]) > R + 1e-10);
                  break;
                case ssc::BoundaryId::x_min:
                  misplaced +=
                    outer == ssc::OuterBoundary::square ?
                      std::abs(x + 1) > 1e-12 :
                      (x > -0.5 || std::hypot(p[0], p[1]) > R + 1e-10);
                  break;
                default:
                  misplaced += std::abs(std::abs(y) - 1) > 1e-12 &&
                               outer == ssc::OuterBoundary::square;
              }
          }
      }
  deallog << "top vertices on the circle r = a: " << on_edge << " (" << n
          << " around)" << std::endl;
  if (outer == ssc::OuterBoundary::circle)
    deallog << "top vertices on the outer circle: " << on_outer_circle
            << std::endl;
  deallog << "boundary faces per id:";
  for (const auto &[id, count] : faces)
    deallog << ' ' << static_cast<unsigned int>(id) << ':' << count;
  deallog << std::endl << "vertices off their side: " << misplaced << std::endl;

  // the patch test on the unrefined mesh (the refined one only adds time)
  const ssc::MeshParameters coarse_parameters = o_grid(outer, 0);
  ssc::BackgroundMesh       coarse(layers, coarse_parameters, MPI_COMM_WORLD);
  coarse.build();
  auto exact = std::make_shared<LinearField>();
  for (const unsigned int degree : {1u, 2u})
    {
      ssc::ElasticityParameters elasticity_parameters;
      elasticity_parameters.degree = degree;
      const auto [l2, h1] =
        patch_test_errors(coarse, layers, elasticity_parameters, exact);
      deallog << "Q" << degree << " mixed: linear field reproduced (L2, H1 "
              << "below 1e-9): " << (l2 < 1e-9 && h1 < 1e-9 ? "yes" : "no")
              << std::endl;
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::LayerStack layers;
  // one material: a linear field is then in equilibrium across the layers
  layers.add_layer("skin", ssc::LayerKind::skin, "1", 0.015, 0.45, 1);
  layers.add_layer("deep", ssc::LayerKind::deep, "3 + 0.05*x", 0.015, 0.45, 1);

  // the depth grading: cell heights from 0.3 mm at the surface, times 1.4
  const std::vector<double> steps =
    ssc::BackgroundMesh::vertical_steps(layers,
                                        o_grid(ssc::OuterBoundary::square, 0));
  deallog << "chart cell heights, bottom to top:";
  for (const double h : steps)
    deallog << ' ' << std::setprecision(4) << h;
  deallog << std::endl;

  check_mesh(layers, ssc::OuterBoundary::square);
  check_mesh(layers, ssc::OuterBoundary::circle);
}
