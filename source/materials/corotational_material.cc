#include <deal.II/base/symmetric_tensor.h>

#include <ssc/materials/corotational_material.h>

namespace ssc
{
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
  CorotationalMaterial::isochoric_response(const Point<3> &,
                                           const Tensor<2, 3>    &F,
                                           SymmetricTensor<2, 3> &tau,
                                           Tensor<4, 3>          &tangent) const
  {
    Tensor<2, 3> P;
    Tensor<4, 3> A;
    isochoric_first_piola(F, P, A);
    push_forward(F, P, A, tau, tangent);
  }


  void
  CorotationalMaterial::isochoric_first_piola(const Tensor<2, 3> &F,
                                              Tensor<2, 3>       &P,
                                              Tensor<4, 3>       &A) const
  {
    Assert(determinant(F) > 0, ExcMessage("det F <= 0"));
    const double mu = reference_moduli.shear_modulus;
    // Psi_iso = mu |J^{-1/3} U - I|^2 = mu (a s - 2 b t + 3) with
    // a = J^{-2/3}, b = J^{-1/3}, s = F:F, t = tr U; the derivatives
    // dJ = J G:dF (G = F^{-T}), dG = -G dF^T G, ds = 2 F:dF, dt = R:dF
    Tensor<2, 3> R, U;
    polar_decomposition(F, R, U);
    const double       J = determinant(F);
    const double       a = std::pow(J, -2. / 3.), b = std::pow(J, -1. / 3.);
    const double       s = scalar_product(F, F), t = trace(U);
    const Tensor<2, 3> G = transpose(invert(F));
    P                    = mu *
        (2. * a * F - 2. / 3. * a * s * G - 2. * b * R + 2. / 3. * b * t * G);

    // dR = R W, W skew with axial vector w: (tr(U) I - U) w =
    // axial(R^T dF - dF^T R); tr(U) I - U is invertible (its eigenvalues
    // are sums of two principal stretches)
    const Tensor<2, 3> K =
      invert(t * Tensor<2, 3>(unit_symmetric_tensor<3>()) - U);
    A = Tensor<4, 3>();
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = 0; l < 3; ++l)
        {
          // dP for dF = e_k (x) e_l
          Tensor<2, 3> dF;
          dF[k][l]             = 1.;
          const Tensor<2, 3> M = transpose(R) * dF;
          const Tensor<1, 3> w =
            K * Tensor<1, 3>(
                  {M[2][1] - M[1][2], M[0][2] - M[2][0], M[1][0] - M[0][1]});
          const Tensor<2, 3> W(
            {{0., -w[2], w[1]}, {w[2], 0., -w[0]}, {-w[1], w[0], 0.}});
          const Tensor<2, 3> dR  = R * W;
          const double       GdF = G[k][l];
          const double       da = -2. / 3. * a * GdF, db = -1. / 3. * b * GdF;
          const double       ds = 2. * F[k][l], dt = R[k][l];
          const Tensor<2, 3> dG = -G * transpose(dF) * G;
          const Tensor<2, 3> dP =
            mu * (2. * da * F + 2. * a * dF - 2. / 3. * (da * s + a * ds) * G -
                  2. / 3. * a * s * dG - 2. * db * R - 2. * b * dR +
                  2. / 3. * (db * t + b * dt) * G + 2. / 3. * b * t * dG);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              A[i][j][k][l] = dP[i][j];
        }
  }


  double
  CorotationalMaterial::energy(const Point<3> &, const Tensor<2, 3> &F) const
  {
    Tensor<2, 3> R, U;
    polar_decomposition(F, R, U);
    const double J  = determinant(F);
    const double mu = reference_moduli.shear_modulus;
    return mu * (std::pow(J, -2. / 3.) * scalar_product(F, F) -
                 2. * std::pow(J, -1. / 3.) * trace(U) + 3.) +
           volumetric_energy.volumetric_energy(J);
  }


  namespace
  {
    const bool registered =
      register_material<CorotationalMaterial, VolumetricEnergyParameters>(
        "corotational",
        "the linear law on the rotated strain U - I of F = R U (finite "
        "rotations, small stretches; hyperelastic, so Newton's tangent is "
        "exact).");
  }
} // namespace ssc
