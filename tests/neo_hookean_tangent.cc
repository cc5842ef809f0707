// The Newton tangent is the derivative of the residual: on a small
// distorted mesh (variable thickness) under a random displacement with
// strains of about 10 % on top of a uniform stretch or compression, every
// column of the assembled tangent matches the
// central difference of the assembled residual -- for neo-Hookean layers in
// the displacement formulation and in the mixed one (mean dilatation), and
// with a tilted finite-strain membrane and a cable embedded, also with the
// tension-field membrane (taut, wrinkled, slack) and the tension-only cable
// (also contracted by 10 %: taut under the 5 % compression);
// the same with a membrane lying in mesh faces and a cable along mesh
// edges, for the corotational law, and for a mean dilatation blended with
// a share of U(J) at the quadrature points (Volumetric stabilisation), and
// with a volumetric growth that varies within the cells; and for Q2 with the
// mixed formulation's dilatation projected onto P1 (three-field), with and
// without stabilisation and growth, and with the mean dilatation (P0) and
// embedded structures. A rigid rotation
// by 60 degrees leaves every law stress-free (objectivity); with a uniform
// growth g, so does the rotated expansion by (1 + g)^{1/3}. A membrane
// that grows with the material (EmbeddedStiffness::grow_with(), a growth
// weight that differs between its triangles) has the tangent of its residual
// too, and with uniform growth of both the rotated expansion is stress-free for
// it as well; at small strain the expansion by g / 3 is (the eigenstrain).
// The fibre-reinforced law (Gasser-Ogden-Holzapfel, Langer's lines turning
// across the block, fibres in tension) in both formulations, with growth:
// the kernel evaluates it at the elastic part F_e of F, so the rotated
// expansion leaves its fibres slack and the block stress-free too.

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/grid/tria_description.h>

#include <cmath>
#include <iostream>
#include <map>
#include <random>

#include <ssc/embedding/clipped_quadrature.h>
#include <ssc/embedding/point_locator.h>
#include <ssc/mechanics/elastic_system.h>
#include <ssc/mechanics/embedded_stiffness.h>
#include <ssc/mesh/background_mesh.h>

#include "quiet_elasticity.h"
#include "tangent_check.h"
#include "tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::LayerStack layers;
  layers.add_layer("skin", ssc::LayerKind::skin, "1 + 0.1*x", 0.02, 0.45, 1);
  layers.add_layer("fat", ssc::LayerKind::SAT, "1.5 - 0.1*y", 0.001, 0.49, 1);
  const ssc::MeshParameters mesh_parameters = uniform_patch(2, 1);
  ssc::BackgroundMesh       mesh(layers, mesh_parameters, MPI_COMM_WORLD);
  mesh.build();

  // a tilted membrane (two triangles) and a cable through the patch
  Triangulation<2, 3> membrane;
  {
    std::vector<CellData<2>> triangles(2, CellData<2>(3));
    triangles[0].vertices    = {0, 1, 2};
    triangles[1].vertices    = {0, 2, 3};
    triangles[1].material_id = 1;
    membrane.create_triangulation(
      std::vector<Point<3>>{Point<3>(-0.9, -0.8, -0.3),
                            Point<3>(0.9, -0.6, -1.9),
                            Point<3>(0.8, 0.9, -1.2),
                            Point<3>(-0.7, 0.8, -0.5)},
      triangles,
      SubCellData());
  }
  Triangulation<1, 3> cable;
  {
    CellData<1> segment;
    segment.vertices = {0, 1};
    cable.create_triangulation(std::vector<Point<3>>{Point<3>(-0.8, 0.3, -0.2),
                                                     Point<3>(0.7, -0.4, -2.0)},
                               std::vector<CellData<1>>{segment},
                               SubCellData());
  }
  // a membrane in the mesh faces of the plane x = 0 (through mesh vertices
  // and along edges) and a cable along the vertical mesh edge x = y = 0
  Triangulation<2, 3> membrane_on_faces;
  {
    std::vector<CellData<2>> triangles(2, CellData<2>(3));
    triangles[0].vertices = {0, 1, 2};
    triangles[1].vertices = {0, 2, 3};
    membrane_on_faces.create_triangulation(
      std::vector<Point<3>>{Point<3>(0, -1, 0),
                            Point<3>(0, 1, 0),
                            Point<3>(0, 1, -2),
                            Point<3>(0, -1, -2)},
      triangles,
      SubCellData());
  }
  Triangulation<1, 3> cable_on_edge;
  {
    CellData<1> segment;
    segment.vertices = {0, 1};
    cable_on_edge.create_triangulation(
      std::vector<Point<3>>{Point<3>(0, 0, 0), Point<3>(0, 0, -2)},
      std::vector<CellData<1>>{segment},
      SubCellData());
  }

  for (const std::string variant :
       {"neo-Hookean, displacement",
        "neo-Hookean, mixed",
        "neo-Hookean, mixed, volumetric stabilisation 0.1",
        "neo-Hookean, mixed + membrane + cable",
        "neo-Hookean, mixed + tension-field membrane + tension-only cable, "
        "stretched",
        "neo-Hookean, mixed + tension-field membrane + tension-only cable, "
        "compressed",
        "neo-Hookean, mixed + tension-field membrane + contracted "
        "tension-only cable, compressed",
        "neo-Hookean, mixed + membrane on mesh faces + cable on a mesh edge",
        "corotational, displacement",
        "corotational, mixed + membrane + cable",
        "neo-Hookean, mixed, growth",
        "corotational, displacement, growth",
        "Q2, neo-Hookean, mixed (P1 dilatation)",
        "Q2, corotational, mixed (P1 dilatation), volumetric stabilisation "
        "0.1, growth",
        "Q2, neo-Hookean, mean dilatation + membrane + cable",
        "neo-Hookean, mixed + growing membrane, growth",
        "neo-Hookean, mixed + growing tension-field membrane, growth",
        "linear, displacement + growing membrane, growth",
        "Gasser-Ogden-Holzapfel, displacement",
        "Gasser-Ogden-Holzapfel, mixed, growth"})
    {
      for (unsigned int l = 0; l < 2; ++l)
        layers.set_model(l,
                         variant.find("corotational") != std::string::npos ?
                           std::string("corotational") :
                         variant.find("linear") == 0 ?
                           std::string("linear") :
                         variant.find("Gasser") == 0 ?
                           std::string("Gasser-Ogden-Holzapfel") :
                           std::string("neo-Hookean"));
      const bool   tension_only = variant.find("tension") != std::string::npos;
      const bool   growth       = variant.find("growth") != std::string::npos;
      const bool   on_faces     = variant.find("faces") != std::string::npos;
      const bool   growing      = variant.find("growing") != std::string::npos;
      const bool   linear       = variant.find("linear") == 0;
      const double stretch =
        variant.find("compressed") != std::string::npos ? -0.05 : 0.2;
      const auto formulation =
        variant.find("displacement") != std::string::npos ?
          ssc::Formulation::displacement :
        variant.find("mean dilatation") != std::string::npos ?
          ssc::Formulation::mean_dilatation :
          ssc::Formulation::mixed;
      ssc::ElasticityParameters parameters;
      parameters.formulation = formulation;
      parameters.degree      = variant.find("Q2") == 0 ? 2 : 1;
      if (variant.find("stabilisation") != std::string::npos)
        parameters.volumetric_stabilisation = 0.1;
      // the fibre-reinforced law with Langer's lines that turn across the
      // block, so that each quadrature point has fibres of its own
      ssc::LayerLawParameters laws;
      ParameterHandler        prm;
      laws.add_parameters(prm, layers.layer_names());
      for (const std::string &layer : layers.layer_names())
        prm.parse_input_from_string(
          "subsection Layer stack\n subsection " + layer +
          "\n  subsection Gasser-Ogden-Holzapfel\n"
          "   set Langer line angle = 30 + 20 * x - 10 * y\n  end\n end\nend\n");
      QuietElasticity     quiet(mesh, layers, parameters, laws);
      ssc::ElasticSystem &elasticity = quiet.elasticity;
      elasticity.field().distribute_dofs();
      elasticity.setup({});
      const ssc::PointLocator                 locator(mesh.triangulation(),
                                      elasticity.field().mapping());
      double                                  area = 0, length = 0;
      std::unique_ptr<ssc::EmbeddedStiffness> septum, ligament;
      if (variant.find("membrane") != std::string::npos)
        {
          septum = std::make_unique<ssc::EmbeddedStiffness>(
            ssc::clipped_quadrature(
              on_faces ? membrane_on_faces : membrane, locator, 2, area),
            ssc::MembraneLaw(ssc::IsotropicModuli(0.1, 0.3), 0.1, tension_only),
            elasticity.field().fe(),
            elasticity.field().mapping(),
            MPI_COMM_WORLD);
          ligament = std::make_unique<ssc::EmbeddedStiffness>(
            ssc::clipped_quadrature(
              on_faces ? cable_on_edge : cable, locator, 2, length),
            ssc::CableLaw(0.1,
                          0.07,
                          tension_only,
                          variant.find("contracted") != std::string::npos ?
                            0.9 :
                            1.),
            elasticity.field().fe(),
            elasticity.field().mapping(),
            MPI_COMM_WORLD);
          if (!growing)
            elasticity.attach(*ligament);
          if (on_faces)
            deallog << variant << ": embedded area " << area << " (exact 4), "
                    << "length " << length << " (exact 2)" << std::endl;
          elasticity.attach(*septum);
        }

      // a growth that varies within the cells; the growing membrane's
      // triangles grow by 0.8 of 0.2 and 0.5
      const auto varying_growth = [](const Point<3> &p) {
        return 0.3 + 0.2 * p[0] - 0.1 * p[2];
      };
      if (growth)
        elasticity.growth().sample(elasticity.field(),
                                   [&](const Point<3> &p, const unsigned int) {
                                     return varying_growth(p);
                                   });
      if (growing)
        septum->grow_with(
          elasticity.growth(),
          [](const types::material_id triangle) {
            return 0.2 + 0.3 * triangle;
          },
          0.8);

      std::mt19937                           generator(5);
      std::uniform_real_distribution<double> uniform(-0.05, 0.05);
      TrilinosWrappers::MPI::Vector u = elasticity.field().owned_solution();
      // a uniform stretch (20 %: septum and cable taut) or compression
      // (5 %: the tension-field septum partly wrinkled, partly slack)
      // plus random strains of about 10 %
      std::map<types::global_dof_index, Point<3>> support;
      DoFTools::map_dofs_to_support_points(elasticity.field().mapping(),
                                           elasticity.field().dof_handler(),
                                           support);
      std::map<types::global_dof_index, unsigned int> component;
      {
        const unsigned int n_per_cell =
          elasticity.field().fe().n_dofs_per_cell();
        std::vector<types::global_dof_index> dofs(n_per_cell);
        for (const auto &cell :
             elasticity.field().dof_handler().active_cell_iterators())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int k = 0; k < n_per_cell; ++k)
              component[dofs[k]] =
                elasticity.field().fe().system_to_component_index(k).first;
          }
      }
      for (const auto &[dof, X] : support)
        u[dof] = stretch * X[component[dof]] + uniform(generator);
      u.compress(VectorOperation::insert);
      const auto [largest_error, largest_entry] =
        tangent_error(elasticity, u, 1e-6, 7);
      deallog << variant << ": largest |K - dr/du| / largest |K| below 1e-6: "
              << (largest_error / largest_entry < 1e-6 ? "yes" : "no")
              << std::endl;

      // objectivity: a rigid rotation by 60 degrees about (1, 2, 3) is
      // stress-free, so the residual vanishes
      {
        const Tensor<1, 3> axis  = Tensor<1, 3>({1., 2., 3.}) / std::sqrt(14.);
        const double       angle = M_PI / 3.;
        const Tensor<2, 3> axis_cross({{0., -axis[2], axis[1]},
                                       {axis[2], 0., -axis[0]},
                                       {-axis[1], axis[0], 0.}});
        Tensor<2, 3>       rotation =
          std::cos(angle) * unit_symmetric_tensor<3>() +
          std::sin(angle) * axis_cross +
          (1. - std::cos(angle)) * outer_product(axis, axis);
        // with a uniform growth g the stress-free state is the rotation
        // of the expansion (1 + g)^{1/3} X
        const double expansion = !growth ? 1. :
                                 linear  ? 1. + 0.4 / 3. :
                                           std::cbrt(1.4);
        if (growth)
          elasticity.growth().sample(elasticity.field(),
                                     [](const Point<3> &, const unsigned int) {
                                       return 0.4;
                                     });
        if (growing)
          septum->grow_with(
            elasticity.growth(),
            [](const types::material_id) { return 0.4; },
            1.);
        if (linear)
          rotation = unit_symmetric_tensor<3>();
        TrilinosWrappers::MPI::Vector rigid(u);
        for (const auto &[dof, X] : support)
          rigid[dof] =
            expansion * (rotation * X)[component[dof]] - X[component[dof]];
        rigid.compress(VectorOperation::insert);
        if (variant.find("contracted") != std::string::npos)
          {
            // the contracted cable is prestressed: the rotation rotates
            // the residual of the reference state, keeping its norm
            TrilinosWrappers::MPI::Vector zero(u);
            zero = 0;
            elasticity.field().set_solution(zero);
            elasticity.assemble(false);
            const double reference =
              elasticity.tangent_system().linearised().rhs.l2_norm();
            elasticity.field().set_solution(rigid);
            elasticity.assemble(false);
            deallog
              << variant << ": rigid rotation of the prestressed "
              << "state, |r| changes by less than 1e-10 of it: "
              << (std::abs(
                    elasticity.tangent_system().linearised().rhs.l2_norm() -
                    reference) < 1e-10 * reference &&
                      reference > 0 ?
                    "yes" :
                    "no")
              << std::endl;
            continue;
          }
        elasticity.field().set_solution(rigid);
        elasticity.assemble(false);
        deallog << variant
                << (linear ? ": uniform growth 0.4, expansion by 0.4 / 3" :
                    growth ? ": uniform growth 0.4, rotated expansion" :
                             ": rigid rotation")
                << ", largest |r| / largest |K| below 1e-10: "
                << (elasticity.tangent_system().linearised().rhs.linfty_norm() /
                          largest_entry <
                        1e-10 ?
                      "yes" :
                      "no")
                << std::endl;
      }
    }
}
