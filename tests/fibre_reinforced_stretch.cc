// Homogeneous stretches of a block of fibre-reinforced skin (the
// Gasser-Ogden-Holzapfel law with its sourced fibres, matrix E = 0.02 MPa)
// through Newton's method with load steps on a 2 x 2 x 2 mm block (symmetry
// rollers on x = -1, y = -1 and the bottom, the faces x = 1 (and y = 1)
// moved, the others free), against the closed form of the law in principal
// stretches: uniaxial tension and compression along and across Langer's
// lines at nu = 0.45 (where the fibres' volume dependence shows), and
// equibiaxial tension at nu = 0.49999 (a compressible block would collapse
// under the fibres' 60 MPa); and equibiaxial again on a
// block whose stress-free state is stretched in the plane by 1.03 (Layer
// stack/.../Prestretch: the law at F F_p, F_p = diag(p, p, 1/p^2), the closed
// form at the stretches l_i of F F_p; the force on x = 1 is still tau_11 over
// the stretch of F); and equibiaxial with fibres recruited at lambda_r = 1.05
// (they join in during the stretch to 1.1) and 1.2 (slack throughout: the
// matrix alone). For F = diag(l1, l2, l3) and fibres a0 = (cos phi, sin
// phi, 0), phi = theta +- gamma, with the lines at theta = 0 or 90 degrees the
// shear terms of the two families cancel and, with r = 1 / lambda_r^2,
//   E     = r (kappa (l1^2 + l2^2 + l3^2)
//              + (1 - 3 kappa)(l1^2 cos^2 phi + l2^2 sin^2 phi)) - 1,
//   tau_f = 4 <psi'> r (kappa l1^2 + (1 - 3 kappa) l1^2 cos^2 phi,
//                       kappa l2^2 + (1 - 3 kappa) l2^2 sin^2 phi,
//                       kappa l3^2),  psi' = k1 E exp(k2 E^2),
//   tau   = dev(mu lb^2) + tau_f + J U'(J),  lb_i = J^{-1/3} l_i;
// the free faces' tau_ii = 0 are solved for their stretches by nested
// bisection, and the force on the face x = 1 is tau_11 / l1 times its 4
// mm^2. The elements reproduce the homogeneous state exactly, so both
// formulations must agree with the closed form to round-off.

#include <deal.II/base/function.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include <ssc/materials/gasser_ogden_holzapfel_material.h>

#include "block_stretch.h"
#include "quiet_elasticity.h"
#include "tests.h"

using namespace dealii;

namespace
{
  constexpr double E_matrix = 0.02;

  /// tau_ii (i = 0, 1, 2) of the law in principal stretches @p l, the
  /// lines at @p theta degrees, Poisson's ratio @p nu.
  std::array<double, 3>
  closed_form_kirchhoff(const ssc::GasserOgdenHolzapfelParameters &fibres,
                        const double                               theta,
                        const double                               nu,
                        const std::array<double, 3>               &l)
  {
    const double mu    = E_matrix / (2 * (1 + nu));
    const double bulk  = E_matrix / (3 * (1 - 2 * nu));
    const double kappa = fibres.fibre_dispersion;
    const double phi   = (theta + fibres.fibre_angle) * numbers::PI / 180.;
    const double J     = l[0] * l[1] * l[2];
    const double c2    = std::cos(phi) * std::cos(phi);
    const double s2    = std::sin(phi) * std::sin(phi);
    const std::array<double, 3> l2 = {l[0] * l[0], l[1] * l[1], l[2] * l[2]};
    const double                r =
      1. / (fibres.recruitment_stretch * fibres.recruitment_stretch);
    const double E = r * (kappa * (l2[0] + l2[1] + l2[2]) +
                          (1 - 3 * kappa) * (l2[0] * c2 + l2[1] * s2)) -
                     1;
    const double                dpsi  = E > 0 ? fibres.fibre_stiffness * E *
                                  std::exp(fibres.fibre_exponent * E * E) :
                                                0.;
    const std::array<double, 3> fibre = {
      4 * dpsi * r * (kappa + (1 - 3 * kappa) * c2) * l2[0],
      4 * dpsi * r * (kappa + (1 - 3 * kappa) * s2) * l2[1],
      4 * dpsi * r * kappa * l2[2]};
    const double          matrix_scale = mu * std::pow(J, -2. / 3.);
    const double          mean         = (l2[0] + l2[1] + l2[2]) / 3;
    const double          pressure = J * 0.5 * bulk * (J - 1 / J); // J U'(J)
    std::array<double, 3> tau;
    for (unsigned int i = 0; i < 3; ++i)
      tau[i] = matrix_scale * (l2[i] - mean) + fibre[i] + pressure;
    return tau;
  }

  /// The stretch in [0.3, 3] at which @p stress (increasing in it) is zero.
  template <typename Stress>
  double
  bisect(const Stress &stress)
  {
    double lo = 0.3, hi = 3.;
    for (unsigned int k = 0; k < 100; ++k)
      {
        const double mid            = 0.5 * (lo + hi);
        (stress(mid) > 0 ? hi : lo) = mid;
      }
    return 0.5 * (lo + hi);
  }

  /// Closed-form forces (N) on the faces x = 1 and y = 1 of the block
  /// stretched by @p lambda along x (and along y if @p equibiaxial), its
  /// stress-free state stretched by @p p in the plane before (the law at
  /// F diag(p, p, 1/p^2), which keeps the volume: tau is the law's there).
  std::array<double, 2>
  closed_form_forces(const ssc::GasserOgdenHolzapfelParameters &fibres,
                     const double                               theta,
                     const double                               nu,
                     const double                               lambda,
                     const bool                                 equibiaxial,
                     const double                               p)
  {
    const auto tau = [&](const double l2, const double l3) {
      return closed_form_kirchhoff(fibres,
                                   theta,
                                   nu,
                                   {lambda * p, l2 * p, l3 / (p * p)});
    };
    // the thickness stretch that frees z for a given l2
    const auto free_z = [&](const double l2) {
      return bisect([&](const double l3) { return tau(l2, l3)[2]; });
    };
    const double l2 = equibiaxial ? lambda : bisect([&](const double s) {
      return tau(s, free_z(s))[1];
    });
    const std::array<double, 3> t = tau(l2, free_z(l2));
    // P_ii = tau_ii / l_i on the reference face of 4 mm^2
    return {t[0] / lambda * 4., t[1] / l2 * 4.};
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  struct Case
  {
    std::string name;
    double      theta;
    double      nu;
    double      lambda;
    bool        equibiaxial;
    double      prestretch;
    double      recruitment = 1.;
  };
  for (const Case &c :
       {Case{"uniaxial along the lines", 0., 0.45, 1.1, false, 1.},
        Case{"uniaxial across the lines", 90., 0.45, 1.1, false, 1.},
        Case{"uniaxial compression along", 0., 0.45, 0.8, false, 1.},
        Case{"equibiaxial", 0., 0.49999, 1.1, true, 1.},
        Case{
          "equibiaxial, prestretched by 1.03", 0., 0.49999, 1.02, true, 1.03},
        Case{"equibiaxial, fibres recruited at 1.05",
             0.,
             0.49999,
             1.1,
             true,
             1.,
             1.05},
        Case{"equibiaxial, fibres recruited at 1.2 (slack)",
             0.,
             0.49999,
             1.1,
             true,
             1.,
             1.2}})
    for (const auto formulation :
         {ssc::Formulation::displacement, ssc::Formulation::mixed})
      {
        ssc::LayerStack layers;
        layers.add_layer("block", ssc::LayerKind::skin, "2", E_matrix, c.nu, 2);
        layers.set_model(0, "Gasser-Ogden-Holzapfel");
        layers.set_prestretch(0, c.prestretch);
        ssc::BackgroundMesh mesh(layers, uniform_patch(2, 1), MPI_COMM_WORLD);
        mesh.build();
        ssc::LayerLawParameters laws;
        ParameterHandler        prm;
        laws.add_parameters(prm, {"block"});
        prm.parse_input_from_string(
          "subsection Layer stack\n subsection block\n"
          "  subsection Gasser-Ogden-Holzapfel\n"
          "   set Langer line angle = " +
          std::to_string(c.theta) + "\n   set Fibre recruitment stretch = " +
          std::to_string(c.recruitment) + "\n  end\n end\nend\n");
        const auto &fibres =
          dynamic_cast<const ssc::GasserOgdenHolzapfelParameters &>(
            laws.of("block", "Gasser-Ogden-Holzapfel"));

        ssc::ElasticityParameters parameters;
        parameters.formulation             = formulation;
        parameters.linear_solver.tolerance = 1e-12;
        ssc::NewtonParameters newton_parameters;
        newton_parameters.relative_tolerance = 1e-12;
        newton_parameters.absolute_tolerance = 1e-14;
        QuietElasticity     quiet(mesh, layers, parameters, laws);
        ssc::ElasticSystem &elasticity = quiet.elasticity;
        elasticity.field().distribute_dofs();
        stretch_block(elasticity,
                      newton_parameters,
                      quiet.pcout,
                      c.lambda,
                      c.equibiaxial,
                      0.02);
        const double force_x = elasticity.reaction(1)[0];
        const double force_y = c.equibiaxial ? elasticity.reaction(4)[1] : 0.;
        const std::array<double, 2> expected = closed_form_forces(
          fibres, c.theta, c.nu, c.lambda, c.equibiaxial, c.prestretch);
        std::ostringstream line;
        line << c.name << ", " << ssc::to_string(formulation) << ", stretch "
             << c.lambda << ": force x " << std::setprecision(6) << force_x
             << " N (closed form " << expected[0] << ")";
        bool agree = std::abs(force_x / expected[0] - 1) < 1e-8;
        if (c.equibiaxial)
          {
            line << ", force y " << force_y << " N (closed form " << expected[1]
                 << ")";
            agree = agree && std::abs(force_y / expected[1] - 1) < 1e-8;
          }
        line << ", relative difference below 1e-8: " << (agree ? "yes" : "no");
        deallog << line.str() << std::endl;
      }
}
