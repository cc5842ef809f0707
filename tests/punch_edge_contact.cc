// Contact of the skin with the rounded edge of a rigid flat punch
// (Punch/Edge contact):
// - the signed distance from the punch (face, rounded edge, wall) has the
//   closed-form values, is continuous across the three parts, and its
//   gradient and Hessian match central differences;
// - on a small two-layer block with part of the surface pressed into the
//   edge, every column of the assembled Newton tangent (neo-Hookean, mean
//   dilatation, contact) matches the central difference of the residual,
//   including the columns of the punch-height dof that the contact couples
//   to; with Q1 and with Q2 elements.

#include <cmath>
#include <iostream>
#include <random>

#include <ssc/contact/rigid_punch_contact.h>
#include <ssc/mechanics/elastic_system.h>
#include <ssc/mesh/background_mesh.h>

#include "quiet_elasticity.h"
#include "tangent_check.h"
#include "tests.h"

using namespace dealii;

namespace
{
  /// Largest difference between the gap's gradient and Hessian and central
  /// differences of the gap and of its gradient at @p x, face @p face.
  double
  derivative_error(const ssc::PunchGeometry &geometry,
                   const Point<3>           &x,
                   const double              face)
  {
    const double        h     = 1e-6;
    const ssc::PunchGap exact = ssc::punch_gap(geometry, x, face);
    double              error = 0;
    for (unsigned int b = 0; b < 4; ++b)
      {
        Point<3> xp = x, xm = x;
        double   fp = face, fm = face;
        if (b < 3)
          {
            xp[b] += h;
            xm[b] -= h;
          }
        else
          {
            fp += h;
            fm -= h;
          }
        const ssc::PunchGap plus  = ssc::punch_gap(geometry, xp, fp);
        const ssc::PunchGap minus = ssc::punch_gap(geometry, xm, fm);
        error                     = std::max(error,
                         std::abs((plus.value - minus.value) / (2 * h) -
                                  exact.gradient[b]));
        for (unsigned int a = 0; a < 4; ++a)
          error =
            std::max(error,
                     std::abs((plus.gradient[a] - minus.gradient[a]) / (2 * h) -
                              exact.hessian[a][b]));
      }
    return error;
  }

  /// Every column of the Newton tangent (neo-Hookean, mean dilatation,
  /// edge contact) against the central difference of the residual, on a
  /// small two-layer block of FE_Q(@p degree) with part of its surface
  /// pressed into the punch's rounded edge.
  void
  check_tangent(const unsigned int degree)
  {
    ssc::LayerStack layers;
    layers.add_layer("skin", ssc::LayerKind::skin, "0.5", 0.02, 0.45, 1);
    layers.add_layer("fat", ssc::LayerKind::SAT, "1.5", 0.001, 0.49, 1);
    for (unsigned int l = 0; l < 2; ++l)
      layers.set_model(l, std::string("neo-Hookean"));
    const ssc::MeshParameters mesh_parameters = uniform_patch(4, 1);
    ssc::BackgroundMesh       mesh(layers, mesh_parameters, MPI_COMM_WORLD);
    mesh.build();
    ssc::ElasticityParameters parameters;
    parameters.formulation = ssc::Formulation::mixed;
    parameters.degree      = degree;
    QuietElasticity     quiet(mesh, layers, parameters);
    ssc::ElasticSystem &elasticity = quiet.elasticity;
    elasticity.field().distribute_dofs();
    types::global_dof_index centre_z = numbers::invalid_dof_index;
    for (const auto &cell :
         elasticity.field().dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).norm() < 1e-12)
          centre_z = cell->vertex_dof_index(v, 2);
    // the skin nodes under the punch's radius are held by it
    const auto held = [](const Point<3> &p) {
      return std::hypot(p[0], p[1]) <= 0.9 * (1. + 1e-10);
    };
    ssc::RigidPunchContact contact({Point<2>(0, 0), 0.9, 0.4},
                                   100.,
                                   0.02,
                                   3.,
                                   elasticity.field().dof_handler(),
                                   elasticity.field().mapping(),
                                   ssc::BoundaryId::top,
                                   held,
                                   [centre_z]() { return centre_z; });
    elasticity.attach(contact);
    elasticity.setup({});
    deallog << "Q" << degree
            << ": faces that can touch the punch: " << contact.n_faces()
            << std::endl;

    // the punch 0.2 mm down and the surface pulled 0.25 mm towards its axis,
    // so that the nodes at r = 1 lie in its rounded edge, plus random
    // displacements of up to 0.05 mm
    std::mt19937                           generator(3);
    std::uniform_real_distribution<double> uniform(-0.05, 0.05);
    TrilinosWrappers::MPI::Vector u = elasticity.field().owned_solution();
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = uniform(generator);
    for (const auto &cell :
         elasticity.field().dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const Point<3> &X = cell->vertex(v);
          const double    r = std::hypot(X[0], X[1]);
          if (std::abs(X[2]) < 1e-12 && r > 0)
            for (unsigned int c = 0; c < 2; ++c)
              u[cell->vertex_dof_index(v, c)] -= 0.25 * X[c] / r;
        }
    u[centre_z] = -0.2;
    u.compress(VectorOperation::insert);
    const auto [area, penetration] = contact.contact_state(u);
    deallog << "Q" << degree << ": area in contact (mm^2) above 0.1: "
            << (area > 0.1 ? "yes" : "no")
            << ", largest penetration (mm) above 0.01: "
            << (penetration > 0.01 ? "yes" : "no") << std::endl;
    const auto [largest_error, largest_entry] =
      tangent_error(elasticity, u, 1e-7, 1);
    deallog << "Q" << degree
            << ": contact: largest |K - dr/du| / largest |K| below 1e-6: "
            << (largest_error / largest_entry < 1e-6 ? "yes" : "no") << " ("
            << (largest_error / largest_entry < 1e-6 ?
                  0. :
                  largest_error / largest_entry)
            << ")" << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  // R = 2, rho = 0.5 (rounding from r = 1.5), face at z = -1
  const ssc::PunchGeometry geometry{Point<2>(0.3, -0.2), 2., 0.5};
  const double             face = -1.;
  const auto               at   = [&](const double r, const double z) {
    const double angle = 0.7;
    return Point<3>(0.3 + r * std::cos(angle), -0.2 + r * std::sin(angle), z);
  };
  struct Case
  {
    const char *where;
    Point<3>    x;
    double      exact;
  };
  const double d = std::hypot(0.4, 0.6); // from the edge's centre line
  for (const Case &c :
       {Case{"below the face", at(0.7, -1.2), 0.2},
        Case{"in the face", at(1.0, -0.9), -0.1},
        Case{"below the edge", at(1.5 + 0.4, -0.5 - 0.6), d - 0.5},
        Case{"in the edge",
             at(1.5 + 0.2, -0.5 - 0.2),
             std::hypot(0.2, 0.2) - 0.5},
        Case{"beside the wall", at(2.3, 0.4), 0.3},
        Case{"in the wall", at(1.9, 0.4), -0.1}})
    {
      const ssc::PunchGap gap = ssc::punch_gap(geometry, c.x, face);
      deallog << "gap " << c.where << ": " << gap.value << " (exact " << c.exact
              << "), derivatives match differences to 1e-6: "
              << (derivative_error(geometry, c.x, face) < 1e-6 ? "yes" : "no")
              << std::endl;
    }
  // continuity where the parts meet: face/edge at r = 1.5, edge/wall at
  // z = -0.5
  double jump = 0;
  for (const double z : {-1.3, -0.8})
    jump =
      std::max(jump,
               std::abs(
                 ssc::punch_gap(geometry, at(1.5 - 1e-12, z), face).value -
                 ssc::punch_gap(geometry, at(1.5 + 1e-12, z), face).value));
  for (const double r : {1.8, 2.2})
    jump =
      std::max(jump,
               std::abs(
                 ssc::punch_gap(geometry, at(r, -0.5 - 1e-12), face).value -
                 ssc::punch_gap(geometry, at(r, -0.5 + 1e-12), face).value));
  deallog << "largest jump of the gap where the parts meet below 1e-10: "
          << (jump < 1e-10 ? "yes" : "no") << std::endl;

  // the tangent with the contact on a small block: top at z = 0, punch
  // of radius 0.9 (edge 0.4) around the centre vertex, whose vertical
  // displacement is the punch height; Q1 and Q2
  for (const unsigned int degree : {1u, 2u})
    check_tangent(degree);
}
