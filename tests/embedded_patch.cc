// Embedded patch tests (docs/architecture.md §9), nu = 0: a block 4 x 4 x 4 mm
// of E = 1 MPa (4^3 Q1 cells) is stretched uniaxially, u = eps (x + 2) e_x,
// with u_x and u_y prescribed on the x faces and rollers on y = -2 and z = -4.
// A planar membrane of thickness t and modulus E_m spanning the block in
// the (x, z) directions adds t L E_m eps cos^3(alpha) to the reaction force
// E L^2 eps (alpha: tilt of the membrane about z), a straight cable E_c A
// eps cos^3(alpha). The error is printed relative to the embedded part:
// exact (1e-10) when the embedded cells lie inside background cells (on
// mesh faces or edges, or cutting cells with aligned edges), converging
// under refinement of the embedded mesh when they cross cell faces
// (tilted). Last: a randomly oriented membrane exerts no force under rigid
// translations and infinitesimal rotations.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/grid/tria_description.h>

#include <cmath>
#include <iomanip>
#include <random>

#include <ssc/embedding/clipped_quadrature.h>
#include <ssc/embedding/point_locator.h>
#include <ssc/mechanics/elastic_system.h>
#include <ssc/mechanics/embedded_stiffness.h>
#include <ssc/mesh/background_mesh.h>

#include "tests.h"

using namespace dealii;

namespace
{
  const double eps = 1e-3, E_m = 2, t = 0.1, E_c = 3, A = 0.05;

  /// The plane through (0, y0, 0) spanned by (cos a, sin a, 0) and e_z, over
  /// the block, as n_s x n_z squares split in two triangles each.
  void
  membrane(Triangulation<2, 3> &tria,
           const double         y0,
           const double         alpha,
           const unsigned int   n_s,
           const unsigned int   n_z)
  {
    std::vector<Point<3>>    vertices;
    std::vector<CellData<2>> cells;
    const double             s_max = 2 / std::cos(alpha);
    for (unsigned int j = 0; j <= n_z; ++j)
      for (unsigned int i = 0; i <= n_s; ++i)
        {
          const double s = -s_max + 2 * s_max * i / n_s;
          vertices.emplace_back(s * std::cos(alpha),
                                y0 + s * std::sin(alpha),
                                -4. + 4. * j / n_z);
        }
    for (unsigned int j = 0; j < n_z; ++j)
      for (unsigned int i = 0; i < n_s; ++i)
        {
          const unsigned int v = j * (n_s + 1) + i;
          for (const auto &corners :
               {std::array<unsigned int, 3>{{v, v + 1, v + n_s + 2}},
                std::array<unsigned int, 3>{{v, v + n_s + 2, v + n_s + 1}}})
            {
              CellData<2> cell(3);
              for (unsigned int k = 0; k < 3; ++k)
                cell.vertices[k] = corners[k];
              cells.push_back(cell);
            }
        }
    tria.create_triangulation(vertices, cells, SubCellData());
  }

  /// A straight cable at height z0 through (0, y0), tilted by alpha about z.
  void
  cable(Triangulation<1, 3> &tria,
        const double         y0,
        const double         z0,
        const double         alpha,
        const unsigned int   n)
  {
    std::vector<Point<3>>    vertices;
    std::vector<CellData<1>> cells;
    const double             s_max = 2 / std::cos(alpha);
    for (unsigned int i = 0; i <= n; ++i)
      {
        const double s = -s_max + 2 * s_max * i / n;
        vertices.emplace_back(s * std::cos(alpha),
                              y0 + s * std::sin(alpha),
                              z0);
      }
    for (unsigned int i = 0; i < n; ++i)
      {
        CellData<1> cell;
        cell.vertices = {i, i + 1};
        cells.push_back(cell);
      }
    tria.create_triangulation(vertices, cells, SubCellData());
  }

  class Block
  {
  public:
    Block()
      : mesh(layers(), mesh_parameters(), MPI_COMM_WORLD)
      , timer(MPI_COMM_WORLD,
              std::cout,
              TimerOutput::never,
              TimerOutput::wall_times)
      , pcout(std::cout, false)
    {
      mesh.build();
      elasticity = std::make_unique<ssc::ElasticSystem>(
        mesh, ssc::LayerMaterials(stack, {}), parameters(), timer);
      elasticity->field().distribute_dofs();
      locator =
        std::make_unique<ssc::PointLocator>(mesh.triangulation(),
                                            elasticity->field().mapping());
    }

    /// Reaction force F_x on the face x = 2 with @p embedded attached: a
    /// membrane (E_m, nu = 0, t) or a cable (E_c, A).
    template <int dim>
    double
    force_x(const Triangulation<dim, 3> &embedded)
    {
      ssc::ElasticSystem elasticity_here(mesh,
                                         ssc::LayerMaterials(stack, {}),
                                         parameters(),
                                         timer);
      elasticity_here.field().distribute_dofs();
      double     covered;
      const auto quadrature =
        ssc::clipped_quadrature(embedded, *locator, 2, covered);
      const ssc::EmbeddedStiffness contribution =
        dim == 2 ? ssc::EmbeddedStiffness(
                     quadrature,
                     ssc::MembraneLaw(ssc::IsotropicModuli(E_m, 0.), t, false),
                     elasticity_here.field().fe(),
                     elasticity_here.field().mapping(),
                     MPI_COMM_WORLD) :
                   ssc::EmbeddedStiffness(quadrature,
                                          ssc::CableLaw(E_c, A, false),
                                          elasticity_here.field().fe(),
                                          elasticity_here.field().mapping(),
                                          MPI_COMM_WORLD);
      elasticity_here.attach(contribution);
      const auto zero = std::make_shared<Functions::ZeroFunction<3>>(3);
      const auto pull = std::make_shared<Functions::ConstantFunction<3>>(
        std::vector<double>{4 * eps, 0., 0.});
      ComponentMask xy(3, true), y(3, false), z(3, false);
      xy.set(2, false);
      y.set(1, true);
      z.set(2, true);
      elasticity_here.setup({{ssc::BoundaryId::x_min, xy, zero, {}},
                             {ssc::BoundaryId::x_max, xy, pull, {}},
                             {ssc::BoundaryId::y_min, y, zero, {}},
                             {ssc::BoundaryId::bottom, z, zero, {}}});
      solve_linear(elasticity_here);
      return elasticity_here.reaction(1)[0];
    }

    ssc::ElasticSystem &
    volume()
    {
      return *elasticity;
    }

    const ssc::PointLocator &
    point_locator()
    {
      return *locator;
    }

  private:
    const ssc::LayerStack &
    layers()
    {
      stack.add_layer("block", ssc::LayerKind::deep, "4", 1., 0., 4);
      return stack;
    }
    static const ssc::MeshParameters &
    mesh_parameters()
    {
      static ssc::MeshParameters p;
      p.patch_length_x  = 4;
      p.patch_length_y  = 4;
      p.cell_size       = 1;
      p.core_half_width = 10;
      return p;
    }
    static const ssc::ElasticityParameters &
    parameters()
    {
      static ssc::ElasticityParameters p;
      p.linear_solver.tolerance      = 1e-13;
      p.linear_solver.max_iterations = 2000;
      return p;
    }

    ssc::LayerStack                     stack;
    ssc::BackgroundMesh                 mesh;
    TimerOutput                         timer;
    ConditionalOStream                  pcout;
    std::unique_ptr<ssc::ElasticSystem> elasticity;
    std::unique_ptr<ssc::PointLocator>  locator;
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  Block        block;
  const double bulk   = 16 * eps; // E L^2 eps
  const auto   report = [&](const std::string &label,
                          const double       force,
                          const double       embedded,
                          const bool         exact) {
    const double       error = std::abs(force - bulk - embedded) / embedded;
    std::ostringstream line;
    line << label << ": relative error of the embedded force ";
    if (exact)
      line << (error < 1e-10 ? "below 1e-10" : "ABOVE 1e-10");
    else
      line << std::scientific << std::setprecision(2) << error;
    deallog << line.str() << std::endl;
  };

  {
    Triangulation<2, 3> on_faces, cutting;
    membrane(on_faces, 0., 0., 4, 4);
    membrane(cutting, 0.3, 0., 4, 4);
    report("membrane on mesh faces",
           block.force_x(on_faces),
           t * 4 * E_m * eps,
           true);
    report("membrane cutting cells, edges on cell faces",
           block.force_x(cutting),
           t * 4 * E_m * eps,
           true);
    const double alpha = 0.3;
    for (const unsigned int n : {1u, 3u, 8u})
      {
        Triangulation<2, 3> tilted;
        membrane(tilted, 0.1, alpha, n, n);
        report("membrane tilted by 0.3 rad, " + std::to_string(2 * n * n) +
                 " triangles",
               block.force_x(tilted),
               t * 4 * E_m * eps * std::pow(std::cos(alpha), 3),
               true);
      }
  }
  {
    Triangulation<1, 3> on_edge, cutting;
    cable(on_edge, 0., -2., 0., 4);
    cable(cutting, 0.3, -1.7, 0., 4);
    report("cable along a mesh edge",
           block.force_x(on_edge),
           E_c * A * eps,
           true);
    report("cable cutting cells, nodes on cell faces",
           block.force_x(cutting),
           E_c * A * eps,
           true);
    const double alpha = 0.3;
    for (const unsigned int n : {1u, 3u, 8u})
      {
        Triangulation<1, 3> tilted;
        cable(tilted, 0.1, -1.7, alpha, n);
        report("cable tilted by 0.3 rad, " + std::to_string(n) + " segments",
               block.force_x(tilted),
               E_c * A * eps * std::pow(std::cos(alpha), 3),
               true);
      }
  }

  // Rigid-body motions: no force from a randomly oriented membrane.
  {
    std::mt19937                           generator(11);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    Tensor<1, 3>                           n(
      {uniform(generator), uniform(generator), uniform(generator)});
    n /= n.norm();
    Tensor<1, 3> a = cross_product_3d(n, Tensor<1, 3>({0.3, 0.9, 0.1}));
    a /= a.norm();
    const Tensor<1, 3>       b = cross_product_3d(n, a);
    std::vector<Point<3>>    vertices;
    std::vector<CellData<2>> cells;
    const Point<3>           centre(0.1, -0.2, -2.1);
    for (unsigned int k = 0; k < 40; ++k)
      {
        const double phi0 = 2 * M_PI * k / 40, phi1 = 2 * M_PI * (k + 1) / 40;
        vertices.push_back(centre);
        vertices.push_back(centre +
                           1.8 * (std::cos(phi0) * a + std::sin(phi0) * b));
        vertices.push_back(centre +
                           1.8 * (std::cos(phi1) * a + std::sin(phi1) * b));
        CellData<2> cell(3);
        cell.vertices = {3 * k, 3 * k + 1, 3 * k + 2};
        cells.push_back(cell);
      }
    Triangulation<2, 3> disk;
    disk.create_triangulation(vertices, cells, SubCellData());
    double                       covered;
    const ssc::EmbeddedStiffness membrane_stiffness(
      ssc::clipped_quadrature(disk, block.point_locator(), 3, covered),
      ssc::MembraneLaw(ssc::IsotropicModuli(E_m, 0.3), t, false),
      block.volume().field().fe(),
      block.volume().field().mapping(),
      MPI_COMM_WORLD);

    const auto      &fe     = block.volume().field().fe();
    const unsigned   n_dofs = fe.n_dofs_per_cell();
    ssc::CellScratch scratch(block.volume().field().mapping(),
                             fe,
                             QGauss<3>(2),
                             update_values);
    ssc::CellCopy    copy;
    Vector<double>   u(n_dofs), r(n_dofs);
    double           largest_force = 0, largest_entry = 0;
    const auto      &support = fe.get_unit_support_points();
    for (const auto &cell :
         block.volume().field().dof_handler().active_cell_iterators())
      {
        copy.reinit(cell, n_dofs);
        scratch.u = 0;
        membrane_stiffness.add_to_cell(cell, scratch, copy);
        const FullMatrix<double> &K = copy.matrix;
        largest_entry               = std::max(largest_entry, K.linfty_norm());
        for (unsigned int mode = 0; mode < 6; ++mode)
          {
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const Point<3> x =
                  block.volume().field().mapping().transform_unit_to_real_cell(
                    cell, support[i]);
                const unsigned int c = fe.system_to_component_index(i).first;
                if (mode < 3)
                  u(i) = (c == mode ? 1. : 0.);
                else
                  {
                    Tensor<1, 3> omega;
                    omega[mode - 3] = 1.;
                    u(i)            = cross_product_3d(omega, x)[c];
                  }
              }
            K.vmult(r, u);
            largest_force = std::max(largest_force, r.linfty_norm());
          }
      }
    deallog << "random membrane under rigid motions: largest nodal force / "
               "largest stiffness entry below 1e-12: "
            << (largest_entry > 0 && largest_force / largest_entry < 1e-12 ?
                  "yes" :
                  "no")
            << std::endl;
  }
}
