#include <cmath>
#include <vector>

#include <ssc/materials/material.h>

namespace ssc
{
  Material::Material(const IsotropicModuli     &moduli,
                     const VolumetricEnergyForm volumetric_form)
    : reference_moduli(moduli)
    , volumetric_energy(moduli.bulk_modulus, volumetric_form)
  {}


  SymmetricTensor<2, 3>
  Material::isochoric_stress(const Point<3> &X, const Tensor<2, 3> &F) const
  {
    SymmetricTensor<2, 3> tau;
    Tensor<4, 3>          tangent;
    isochoric_response(X, F, tau, tangent);
    return tau;
  }


  SymmetricTensor<2, 3>
  Material::cauchy_stress(const Point<3>     &X,
                          const Tensor<2, 3> &F,
                          const double        gamma) const
  {
    // the energy gamma (W_iso(F_e) + U(J / gamma)) of growth F_g =
    // gamma^{1/3} I: tau = gamma tau_iso(F_e) + J U'(J / gamma) I
    return grown_cauchy_stress(isochoric_stress(X, elastic_part(F, gamma)),
                               determinant(F),
                               gamma);
  }


  SymmetricTensor<2, 3>
  Material::grown_cauchy_stress(const SymmetricTensor<2, 3> &tau_iso,
                                const double                 J,
                                const double                 gamma) const
  {
    Assert(J > 0, ExcMessage("Cauchy stress of an inverted state."));
    return (gamma * tau_iso + J * volumetric_energy.pressure(J / gamma) *
                                unit_symmetric_tensor<3>()) /
           J;
  }


  SymmetricTensor<2, 3>
  Material::accepted_cauchy_stress(
    const Point<3>                &X,
    const Tensor<2, 3>            &F,
    const double                   gamma,
    const ArrayView<const double> &committed) const
  {
    if (n_history_variables() == 0)
      return cauchy_stress(X, F, gamma);
    // a step of no time from the accepted state: that state's stress
    std::vector<double>  trial(n_history_variables());
    MaterialPointHistory history{committed, make_array_view(trial), 0.};
    return grown_cauchy_stress(isochoric_stress_in_step(X,
                                                        elastic_part(F, gamma),
                                                        history),
                               determinant(F),
                               gamma);
  }


  SymmetricTensor<4, 3>
  Material::small_strain_tangent() const
  {
    SymmetricTensor<2, 3> tau;
    Tensor<4, 3>          a;
    isochoric_response(Point<3>(), unit_symmetric_tensor<3>(), tau, a);
    // at F = I the stress vanishes and the tangent of an objective law has
    // the minor symmetries; symmetrising keeps exactly that part
    SymmetricTensor<4, 3> c;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int k = i; k < 3; ++k)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int l = j; l < 3; ++l)
            c[i][k][j][l] = 0.25 * (a[i][k][j][l] + a[k][i][j][l] +
                                    a[i][k][l][j] + a[k][i][l][j]);
    return c;
  }


  void
  push_forward(const Tensor<2, 3>    &F,
               const Tensor<2, 3>    &P,
               const Tensor<4, 3>    &A,
               SymmetricTensor<2, 3> &tau,
               Tensor<4, 3>          &tangent)
  {
    tau = symmetrize(P * transpose(F));
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int l = 0; l < 3; ++l)
            {
              double value = 0;
              for (unsigned int m = 0; m < 3; ++m)
                for (unsigned int o = 0; o < 3; ++o)
                  value += F[k][m] * A[i][m][j][o] * F[l][o];
              tangent[i][k][j][l] = value;
            }
  }


  double
  von_mises(const SymmetricTensor<2, 3> &sigma)
  {
    const SymmetricTensor<2, 3> s = deviator(sigma);
    return std::sqrt(1.5 * scalar_product(s, s));
  }
} // namespace ssc
