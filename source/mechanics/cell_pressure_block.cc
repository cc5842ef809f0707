#include <algorithm>

#include <ssc/linear_algebra/cell_matrix_product.h>
#include <ssc/mechanics/cell_pressure_block.h>

namespace ssc
{
  void
  CellPressureBlock::augment()
  {
    const unsigned int n_p = mass.m(), n = coupling.n();
    AssertDimension(pressure.m(), n_p);
    AssertDimension(reduced.m(), n);
    FullMatrix<double> mass_inverse(n_p, n_p), C_inverse(n_p, n_p);
    mass_inverse.invert(mass);
    C_inverse.invert(pressure);
    // lambda_max(C M^{-1}) <= tr(C M^{-1}): gamma M^{-1} <= C^{-1} / 2
    double trace = 0;
    for (unsigned int a = 0; a < n_p; ++a)
      for (unsigned int b = 0; b < n_p; ++b)
        trace += pressure(a, b) * mass_inverse(b, a);
    // The larger gamma, the closer M / (2 mu + gamma) + C is to the Schur
    // complement, and the stiffer the displacement block is in dilatation.
    // 8 mu: on the layered punch at nu = 0.4999 (Q2-P1, V-cycle on the
    // displacement block) 27 FGMRES iterations at 77k and 583k DoFs, where
    // 2 mu needed 35 and 45, 4 mu 28 and 34; 12 and 16 mu needed 33 and 38
    // at 77k (benchmarks/multigrid_layered, "Nearly incompressible layers").
    const double gamma = std::min(8. * shear_modulus, 0.5 / trace);

    // K_0 += gamma B^T M^{-1} B
    FullMatrix<double> M_inverse_B(n_p, n);
    multiply(M_inverse_B, mass_inverse, coupling);
    FullMatrix<double> volumetric(n, n);
    multiply(volumetric, coupling, M_inverse_B, Transposed::left);
    reduced.add(gamma, volumetric);
    // C = (C^{-1} - gamma M^{-1})^{-1}
    C_inverse.add(-gamma, mass_inverse);
    pressure.invert(C_inverse);
    schur = pressure;
    schur.add(1. / (2. * shear_modulus + gamma), mass);
  }
} // namespace ssc
