#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

#include <ssc/materials/material_registry.h>
#include <ssc/materials/volumetric_energy_parameters.h>

namespace ssc
{
  namespace
  {
    /**
     * Saint Venant-Kirchhoff on the isochoric strain, plus U(J):
     *   Psi = mu Ebar:Ebar + U(J),  Ebar = (J^{-2/3} C - I) / 2,
     * the quadratic law in the Green-Lagrange strain written with the
     * isochoric/volumetric split of the other finite-strain laws (so the
     * mixed formulations and growth treat it alike; the textbook form
     * lambda/2 (tr E)^2 + mu E:E softens without bound in compression).
     * To second order it is mu |dev eps|^2 + kappa/2 (tr eps)^2, the
     * linear law. With g = J^{-2/3} = (det C)^{-1/3} and h = Ebar:C,
     *   S      = 2 mu g (Ebar - h/3 C^{-1}),
     *   dS/dC  = 2 mu [ g^2/2 (I^s - C (x) C^{-1}/3) - g/3 Ebar (x) C^{-1}
     *            - 1/3 C^{-1} (x) (g Ebar + g^2/2 (C - (C:C)/3 C^{-1})
     *                              - g h/3 C^{-1})
     *            - g h/3 dC^{-1}/dC ],
     * and P = F S, dP_iK/dF_jL = delta_ij S_KL + 2 F_iI (dS/dC)_IKLM F_jM,
     * pushed forward like the corotational law.
     */
    class SaintVenantKirchhoffMaterial : public Material
    {
    public:
      SaintVenantKirchhoffMaterial(const IsotropicModuli            &moduli,
                                   const VolumetricEnergyParameters &parameters)
        : Material(moduli, parameters.form)
      {}

      Kinematics
      kinematics() const override
      {
        return Kinematics::finite_strain;
      }

      void
      isochoric_response(const Point<3> &,
                         const Tensor<2, 3>    &F,
                         SymmetricTensor<2, 3> &tau,
                         Tensor<4, 3>          &tangent) const override
      {
        Assert(determinant(F) > 0, ExcMessage("det F <= 0"));
        const double                mu        = reference_moduli.shear_modulus;
        const SymmetricTensor<2, 3> C         = symmetrize(transpose(F) * F);
        const SymmetricTensor<2, 3> C_inverse = invert(C);
        const SymmetricTensor<2, 3> I         = unit_symmetric_tensor<3>();
        const double                g     = std::pow(determinant(C), -1. / 3.);
        const SymmetricTensor<2, 3> E_bar = 0.5 * (g * C - I);
        const double                h     = E_bar * C;

        const SymmetricTensor<2, 3> S =
          2. * mu * g * (E_bar - h / 3. * C_inverse);

        SymmetricTensor<4, 3> dC_inverse_dC;
        for (unsigned int A = 0; A < 3; ++A)
          for (unsigned int B = A; B < 3; ++B)
            for (unsigned int M = 0; M < 3; ++M)
              for (unsigned int N = M; N < 3; ++N)
                dC_inverse_dC[A][B][M][N] =
                  -0.5 * (C_inverse[A][M] * C_inverse[N][B] +
                          C_inverse[A][N] * C_inverse[M][B]);
        const SymmetricTensor<2, 3> d_gh_dC =
          g * E_bar + 0.5 * g * g * (C - (C * C) / 3. * C_inverse) -
          g * h / 3. * C_inverse;
        const SymmetricTensor<4, 3> dS_dC =
          2. * mu *
          (0.5 * g * g *
             (identity_tensor<3>() - outer_product(C, C_inverse) / 3.) -
           g / 3. * outer_product(E_bar, C_inverse) -
           outer_product(C_inverse, d_gh_dC) / 3. - g * h / 3. * dC_inverse_dC);

        const Tensor<2, 3> P = F * Tensor<2, 3>(S);
        Tensor<4, 3>       A;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int K = 0; K < 3; ++K)
            for (unsigned int j = 0; j < 3; ++j)
              for (unsigned int L = 0; L < 3; ++L)
                {
                  double value = (i == j ? S[K][L] : 0.);
                  for (unsigned int I_ = 0; I_ < 3; ++I_)
                    for (unsigned int M = 0; M < 3; ++M)
                      value += 2. * F[i][I_] * dS_dC[I_][K][L][M] * F[j][M];
                  A[i][K][j][L] = value;
                }
        push_forward(F, P, A, tau, tangent);
      }

      double
      energy(const Point<3> &, const Tensor<2, 3> &F) const override
      {
        const SymmetricTensor<2, 3> C = symmetrize(transpose(F) * F);
        const SymmetricTensor<2, 3> E_bar =
          0.5 *
          (std::pow(determinant(C), -1. / 3.) * C - unit_symmetric_tensor<3>());
        return reference_moduli.shear_modulus * (E_bar * E_bar) +
               volumetric_energy.volumetric_energy(determinant(F));
      }
    };

    const bool registered = register_material<SaintVenantKirchhoffMaterial,
                                              VolumetricEnergyParameters>(
      "Saint Venant-Kirchhoff",
      "mu Ebar:Ebar + U(J) with the isochoric Green-Lagrange strain Ebar = "
      "(J^{-2/3} C - I)/2: the quadratic law of the classic codes, on the "
      "isochoric/volumetric split of the other finite-strain laws.");
  } // namespace
} // namespace ssc
