#include <deal.II/base/symmetric_tensor.h>

#include <ssc/mechanics/corotational_material.h>

namespace ssc
{
  CorotationalMaterial::CorotationalMaterial(const double youngs_modulus,
                                             const double poisson_ratio)
    : VolumetricEnergy(youngs_modulus / (3. * (1. - 2. * poisson_ratio)))
    , mu(youngs_modulus / (2. * (1. + poisson_ratio)))
  {}


  void
  CorotationalMaterial::polar_decomposition(const Tensor<2, 3> &F,
                                            Tensor<2, 3>       &R,
                                            Tensor<2, 3>       &U)
  {
    // U = sqrt(F^T F) from the eigenpairs of C; Jacobi keeps the
    // eigenvectors orthonormal also for (nearly) repeated eigenvalues
    const auto   eigen = eigenvectors(symmetrize(transpose(F) * F),
                                    SymmetricTensorEigenvectorMethod::jacobi);
    Tensor<2, 3> U_inverse;
    U = Tensor<2, 3>();
    for (const auto &[value, vector] : eigen)
      {
        const double stretch = std::sqrt(value);
        U += stretch * outer_product(vector, vector);
        U_inverse += (1. / stretch) * outer_product(vector, vector);
      }
    R = F * U_inverse;
  }


  void
  CorotationalMaterial::deviatoric(const Tensor<2, 3> &F,
                                   Tensor<2, 3>       &P,
                                   Tensor<4, 3>       &A) const
  {
    Tensor<2, 3> R, U;
    polar_decomposition(F, R, U);
    const double trace_U = trace(U);
    P                    = 2. * mu * (F - trace_U / 3. * R);

    // (tr(U) I - U)^{-1}: its eigenvalues are sums of two principal
    // stretches, so it is invertible
    const Tensor<2, 3> K =
      invert(trace_U * Tensor<2, 3>(unit_symmetric_tensor<3>()) - U);
    A = Tensor<4, 3>();
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = 0; l < 3; ++l)
        {
          // dP for dF = e_k (x) e_l
          Tensor<2, 3> dF;
          dF[k][l]             = 1.;
          const Tensor<2, 3> M = transpose(R) * dF;
          const Tensor<1, 3> rhs(
            {M[2][1] - M[1][2], M[0][2] - M[2][0], M[1][0] - M[0][1]});
          const Tensor<1, 3> w = K * rhs;
          const Tensor<2, 3> W(
            {{0., -w[2], w[1]}, {w[2], 0., -w[0]}, {-w[1], w[0], 0.}});
          const Tensor<2, 3> dR = R * W;
          const Tensor<2, 3> dP =
            2. * mu * (dF - scalar_product(R, dF) / 3. * R - trace_U / 3. * dR);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              A[i][j][k][l] = dP[i][j];
        }
  }


  double
  CorotationalMaterial::energy(const Tensor<2, 3> &F) const
  {
    Tensor<2, 3> R, U;
    polar_decomposition(F, R, U);
    const double trace_U = trace(U);
    return mu * (scalar_product(F, F) - trace_U * trace_U / 3.) +
           volumetric_energy(determinant(F));
  }
} // namespace ssc
