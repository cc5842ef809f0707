// Every registered law of materials/ (made by make_material(), as for a
// layer, with its default parameters) against
// finite differences of itself, at a random deformation gradient and at an
// in-plane stretch, at one material point (the fibre-reinforced law's
// fibres slack at the first, in tension at the second, as the test
// prints), and two laws wrapped with an in-plane prestretch
// (PrestretchedMaterial; not isotropic at F = I): the first
// Piola stress of the isochoric part (tau_iso F^{-T}) plus U'(J) J F^{-T} is
// the derivative of the energy, the spatial tangent pulled back is the
// derivative of that stress, the law is objective (tau(QF) = Q tau Q^T), its
// stress alone (what a residual asks for) is the stress of its response, and
// its small-strain tangent is the isotropic 2 mu (I^s - 1/3 1 (x) 1). The
// linear law: its Cauchy stress is the derivative of its energy. A new law
// is checked here as soon as it registers itself.

#include <cmath>
#include <iomanip>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <ssc/materials/layer_materials.h>

#include "tests.h"

using namespace dealii;

namespace
{
  /// The material point every law is evaluated at (a law with a field,
  /// the fibres along Langer's lines, reads it there).
  const Point<3> X(0.3, -0.2, -0.5);

  /// P = dW/dF by central differences of the energy.
  Tensor<2, 3>
  energy_gradient(const ssc::Material &law, const Tensor<2, 3> &F)
  {
    const double h = 1e-6;
    Tensor<2, 3> P;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        {
          Tensor<2, 3> plus(F), minus(F);
          plus[i][j] += h;
          minus[i][j] -= h;
          P[i][j] = (law.energy(X, plus) - law.energy(X, minus)) / (2 * h);
        }
    return P;
  }

  /// The first Piola stress of the isochoric part, tau_iso F^{-T}.
  Tensor<2, 3>
  isochoric_piola(const ssc::Material &law, const Tensor<2, 3> &F)
  {
    SymmetricTensor<2, 3> tau;
    Tensor<4, 3>          a;
    law.isochoric_response(X, F, tau, a);
    return Tensor<2, 3>(tau) * transpose(invert(F));
  }

  /// Largest |entry| of @p T.
  template <int rank>
  double
  largest(const Tensor<rank, 3> &T)
  {
    double value = 0;
    for (unsigned int k = 0; k < Tensor<rank, 3>::n_independent_components; ++k)
      value = std::max(value, std::abs(T[T.unrolled_to_component_indices(k)]));
    return value;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::mt19937                           generator(11);
  std::uniform_real_distribution<double> uniform(-0.25, 0.25);
  Tensor<2, 3>                           random = unit_symmetric_tensor<3>();
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      random[i][j] += uniform(generator);
  // the random state leaves the fibres of the Gasser-Ogden-Holzapfel law
  // slack; a stretch in the plane of the skin puts both families in tension
  Tensor<2, 3> stretched = 0.2 * (random - unit_symmetric_tensor<3>());
  stretched[0][0] += 1.3;
  stretched[1][1] += 1.2;
  stretched[2][2] += 0.7;
  // a rotation for the objectivity check
  const Tensor<1, 3> axis  = Tensor<1, 3>({2., -1., 2.}) / 3.;
  const double       angle = 1.1;
  const Tensor<2, 3> cross({{0., -axis[2], axis[1]},
                            {axis[2], 0., -axis[0]},
                            {-axis[1], axis[0], 0.}});
  const Tensor<2, 3> Q = std::cos(angle) * unit_symmetric_tensor<3>() +
                         std::sin(angle) * cross +
                         (1. - std::cos(angle)) * outer_product(axis, axis);
  for (const auto &[state, F] :
       {std::make_pair(std::string("random F"), random),
        std::make_pair(std::string("stretched"), stretched)})
    {
      deallog << state << ": det F = " << determinant(F) << std::endl;
      // every registered law, and two laws wrapped with an in-plane
      // prestretch (PrestretchedMaterial)
      // (model, prestretch, fibre recruitment stretch)
      std::vector<std::tuple<std::string, double, double>> laws;
      for (const std::string &name : ssc::MaterialRegistry::names())
        laws.emplace_back(name, 1., 1.);
      laws.emplace_back("neo-Hookean", 1.1, 1.);
      laws.emplace_back("Gasser-Ogden-Holzapfel", 1.05, 1.);
      laws.emplace_back("Gasser-Ogden-Holzapfel", 1., 1.1);
      for (const auto &[model, prestretch, recruitment] : laws)
        {
          std::string name = model;
          if (prestretch != 1.)
            name +=
              " prestretched by " + std::to_string(prestretch).substr(0, 4);
          if (recruitment != 1.)
            name += " recruited at " + std::to_string(recruitment).substr(0, 3);
          ssc::Layer layer;
          layer.name           = "skin";
          layer.youngs_modulus = 0.02;
          layer.poisson_ratio  = 0.45;
          layer.material_model = model;
          layer.prestretch     = prestretch;
          ssc::LayerLawParameters layer_laws;
          ParameterHandler        prm;
          layer_laws.add_parameters(prm, {"skin"});
          prm.parse_input_from_string(
            "subsection Layer stack\n subsection skin\n"
            "  subsection Gasser-Ogden-Holzapfel\n"
            "   set Fibre recruitment stretch = " +
            std::to_string(recruitment) + "\n  end\n end\nend\n");
          const auto         law  = ssc::make_material(layer, layer_laws);
          const double       mu   = law->moduli().shear_modulus;
          const double       J    = determinant(F);
          const Tensor<2, 3> P_fd = energy_gradient(*law, F);
          Tensor<2, 3>       P;
          if (law->kinematics() == ssc::Kinematics::small_strain)
            P = Tensor<2, 3>(law->cauchy_stress(X, F));
          else
            P = isochoric_piola(*law, F) +
                law->volumetric().pressure(J) * J * transpose(invert(F));
          deallog << name << ", " << state
                  << ": stress is the derivative of the energy: "
                  << (largest(P - P_fd) < 1e-8 * largest(P) ? "yes" : "no")
                  << std::endl;

          // the tangent: A_iKjL = F^{-1}_Kk a_ikjl F^{-1}_Ll against dP/dF
          SymmetricTensor<2, 3> tau;
          Tensor<4, 3>          a, A, A_fd;
          law->isochoric_response(X, F, tau, a);
          const Tensor<2, 3> F_inverse = invert(F);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int K = 0; K < 3; ++K)
              for (unsigned int j = 0; j < 3; ++j)
                for (unsigned int L = 0; L < 3; ++L)
                  for (unsigned int k = 0; k < 3; ++k)
                    for (unsigned int l = 0; l < 3; ++l)
                      A[i][K][j][L] +=
                        F_inverse[K][k] * a[i][k][j][l] * F_inverse[L][l];
          const double h = 1e-6;
          for (unsigned int j = 0; j < 3; ++j)
            for (unsigned int L = 0; L < 3; ++L)
              {
                Tensor<2, 3> plus(F), minus(F);
                plus[j][L] += h;
                minus[j][L] -= h;
                const Tensor<2, 3> dP =
                  (isochoric_piola(*law, plus) - isochoric_piola(*law, minus)) /
                  (2 * h);
                for (unsigned int i = 0; i < 3; ++i)
                  for (unsigned int K = 0; K < 3; ++K)
                    A_fd[i][K][j][L] = dP[i][K];
              }
          // the linear law's isochoric response is the small-strain one, whose
          // "tangent" is that of sigma in eps, not of tau F^{-T}
          if (law->kinematics() == ssc::Kinematics::finite_strain)
            deallog << name << ", " << state
                    << ": tangent is the derivative of the stress: "
                    << (largest(A - A_fd) < 1e-6 * largest(A) ? "yes" : "no")
                    << std::endl;

          SymmetricTensor<2, 3> tau_rotated;
          law->isochoric_response(X, Q * F, tau_rotated, a);
          if (law->kinematics() == ssc::Kinematics::finite_strain)
            deallog << name << ", " << state << ": objective: "
                    << (largest(Tensor<2, 3>(tau_rotated) -
                                Q * Tensor<2, 3>(tau) * transpose(Q)) <
                            1e-12 * largest(Tensor<2, 3>(tau)) ?
                          "yes" :
                          "no")
                    << std::endl;

          // the residual's stress-only path (Material::isochoric_stress())
          if (law->kinematics() == ssc::Kinematics::finite_strain)
            deallog << name << ", " << state
                    << ": the stress alone is the response's stress: "
                    << (largest(
                          Tensor<2, 3>(law->isochoric_stress(X, F) - tau)) <=
                            1e-14 * largest(Tensor<2, 3>(tau)) ?
                          "yes" :
                          "no")
                    << std::endl;

          // at F = I a prestretched law is pre-stressed, not isotropic
          if (prestretch == 1.)
            {
              const SymmetricTensor<2, 3> I = unit_symmetric_tensor<3>();
              const SymmetricTensor<4, 3> isotropic =
                2. * mu *
                (identity_tensor<3>() - 1. / 3. * outer_product(I, I));
              const SymmetricTensor<4, 3> difference =
                law->small_strain_tangent() - isotropic;
              double error = 0;
              for (unsigned int k = 0; k < difference.n_independent_components;
                   ++k)
                error =
                  std::max(error, std::abs(difference.access_raw_entry(k)));
              deallog << name << ", " << state
                      << ": small-strain tangent 2 mu (I^s - 1/3 1 (x) 1): "
                      << (error < 1e-12 * mu ? "yes" : "no") << std::endl;
            }

          // whether the state puts the fibres in tension: the stress differs
          // from that of the matrix alone
          if (model == "Gasser-Ogden-Holzapfel" && prestretch == 1.)
            {
              layer.material_model = "neo-Hookean";
              const auto matrix    = ssc::make_material(layer);
              deallog << name << ", " << state << ": fibres in tension: "
                      << (largest(Tensor<2, 3>(
                            law->isochoric_stress(X, F) -
                            matrix->isochoric_stress(X, F))) > 1e-3 * mu ?
                            "yes" :
                            "no")
                      << std::endl;
            }
        }
    }

  // both volumetric energies: U' and U'' are the derivatives of U, and U
  // is kappa/2 (J - 1)^2 to second order (the two forms differ at third)
  for (const auto form : {ssc::VolumetricEnergyForm::logarithmic,
                          ssc::VolumetricEnergyForm::quadratic})
    {
      const ssc::VolumetricEnergy U(2.5, form);
      const std::string           name       = ssc::to_string(form);
      const double                h          = 1e-6;
      bool                        consistent = true;
      for (const double J : {0.3, 0.8, 1.0, 1.4})
        {
          const double dU =
            (U.volumetric_energy(J + h) - U.volumetric_energy(J - h)) / (2 * h);
          const double d2U = (U.pressure(J + h) - U.pressure(J - h)) / (2 * h);
          consistent =
            consistent && std::abs(dU - U.pressure(J)) < 1e-6 * U.kappa &&
            std::abs(d2U - U.pressure_derivative(J)) < 1e-6 * U.kappa;
        }
      const double e     = 1e-3;
      const double ratio = U.volumetric_energy(1 + e) / (0.5 * U.kappa * e * e);
      deallog << name << " U(J): derivatives consistent: "
              << (consistent ? "yes" : "no") << "; U(1 + e) / (kappa/2 e^2) "
              << "- 1 at e = 1e-3: " << std::setprecision(2)
              << (std::abs(ratio - 1.) < 1e-9 ? 0. : ratio - 1.)
              << std::setprecision(6) << std::endl;
    }
}
