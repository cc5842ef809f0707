#include <deal.II/base/symmetric_tensor.h>

#include <array>

#include <ssc/linear_algebra/cell_matrix_product.h>
#include <ssc/mechanics/pressure_basis.h>
#include <ssc/mechanics/small_strain_kernel.h>

namespace ssc
{
  namespace
  {
    /**
     * Gradients, at unit point @p xi of a cell with Jacobian determinant
     * @p det_J there, of the three Wilson bubbles P_d = 4 xi_d (1 - xi_d)
     * taken with the centre Jacobian @p J0 (Taylor's modification:
     * (det J0 / det J) J0^{-T} grad_xi P_d), so that they integrate to zero
     * over the cell and the element passes the patch test when distorted.
     */
    std::array<Tensor<1, 3>, 3>
    incompatible_mode_gradients(const Tensor<2, 3> &J0,
                                const Point<3>     &xi,
                                const double        det_J)
    {
      const Tensor<2, 3>          J0_inverse_transpose = transpose(invert(J0));
      const double                ratio = determinant(J0) / det_J;
      std::array<Tensor<1, 3>, 3> gradients;
      for (unsigned int d = 0; d < 3; ++d)
        {
          Tensor<1, 3> reference;
          reference[d] = 4. * (1. - 2. * xi[d]);
          gradients[d] = ratio * (J0_inverse_transpose * reference);
        }
      return gradients;
    }


    /// Jacobian of the trilinear map of a hexahedron at its centre.
    Tensor<2, 3>
    centre_jacobian(const DoFHandler<3>::active_cell_iterator &cell)
    {
      Tensor<2, 3> J;
      for (unsigned int v = 0; v < 8; ++v)
        for (unsigned int d = 0; d < 3; ++d)
          {
            // +1/4 on the vertices with xi_d = 1, -1/4 on those with 0
            const double sign = ((v >> d) & 1) ? 0.25 : -0.25;
            for (unsigned int i = 0; i < 3; ++i)
              J[i][d] += sign * cell->vertex(v)[i];
          }
      return J;
    }


    /**
     * Static condensation of the modes n_dofs, ..., n_modes - 1 of @p
     * matrix and @p rhs (they carry no load of their own but for @p rhs's
     * entries): K = K_uu - K_ua K_aa^{-1} K_au, f = f_u - K_ua K_aa^{-1} f_a.
     */
    void
    condense(const FullMatrix<double> &matrix,
             const Vector<double>     &rhs,
             const unsigned int        n_dofs,
             FullMatrix<double>       &cell_matrix,
             Vector<double>           &cell_rhs)
    {
      const unsigned int n_modes = matrix.m(), n_a = n_modes - n_dofs;
      FullMatrix<double> K_ua(n_dofs, n_a), K_aa(n_a, n_a);
      for (unsigned int i = 0; i < n_modes; ++i)
        for (unsigned int j = n_dofs; j < n_modes; ++j)
          (i < n_dofs ? K_ua(i, j - n_dofs) : K_aa(i - n_dofs, j - n_dofs)) =
            matrix(i, j);
      K_aa.gauss_jordan();
      FullMatrix<double> K_aa_inv_K_au(n_a, n_dofs);
      multiply(K_aa_inv_K_au, K_aa, K_ua, Transposed::right);
      FullMatrix<double> correction(n_dofs, n_dofs);
      multiply(correction, K_ua, K_aa_inv_K_au);
      for (unsigned int i = 0; i < n_dofs; ++i)
        for (unsigned int j = 0; j < n_dofs; ++j)
          cell_matrix(i, j) = matrix(i, j) - correction(i, j);
      Vector<double> f_a(n_a), K_aa_inv_f_a(n_a), f_correction(n_dofs);
      for (unsigned int a = 0; a < n_a; ++a)
        f_a(a) = rhs(n_dofs + a);
      K_aa.vmult(K_aa_inv_f_a, f_a);
      K_ua.vmult(f_correction, K_aa_inv_f_a);
      for (unsigned int i = 0; i < n_dofs; ++i)
        cell_rhs(i) += rhs(i) - f_correction(i);
    }


    /**
     * The pressure block of the cell (CellPressureBlock) from its
     * deviatoric matrix @p deviatoric over the strain modes, the coupling
     * @p coupling of the pressure modes to them, the pressure mass matrix
     * @p mass, the bulk modulus @p kappa and the shear modulus @p mu: the
     * system [K B^T; B -M / kappa] on (u, alpha, p) with the incompatible
     * modes alpha (modes n_dofs, ...) eliminated: K_0 = K_uu - K_ua
     * K_aa^{-1} K_au, B = B_u - B_a K_aa^{-1} K_au, C = M / kappa + B_a
     * K_aa^{-1} B_a^T. Condensing its pressure gives the cell matrix.
     */
    void
    pressure_block(const FullMatrix<double> &deviatoric,
                   const FullMatrix<double> &coupling,
                   const FullMatrix<double> &mass,
                   const double              kappa,
                   const double              mu,
                   const unsigned int        n_dofs,
                   CellPressureBlock        &block)
    {
      const unsigned int n_modes = deviatoric.m(), n_a = n_modes - n_dofs;
      const unsigned int n_p = mass.m();
      block.reduced.reinit(n_dofs, n_dofs);
      block.coupling.reinit(n_p, n_dofs);
      block.pressure.reinit(n_p, n_p);
      for (unsigned int i = 0; i < n_dofs; ++i)
        for (unsigned int j = 0; j < n_dofs; ++j)
          block.reduced(i, j) = deviatoric(i, j);
      for (unsigned int a = 0; a < n_p; ++a)
        {
          for (unsigned int i = 0; i < n_dofs; ++i)
            block.coupling(a, i) = coupling(a, i);
          for (unsigned int b = 0; b < n_p; ++b)
            block.pressure(a, b) = mass(a, b) / kappa;
        }
      if (n_a > 0)
        {
          // G = K_aa^{-1} [K_au, B_a^T]
          FullMatrix<double> K_aa(n_a, n_a), rhs(n_a, n_dofs + n_p);
          for (unsigned int a = 0; a < n_a; ++a)
            {
              for (unsigned int b = 0; b < n_a; ++b)
                K_aa(a, b) = deviatoric(n_dofs + a, n_dofs + b);
              for (unsigned int j = 0; j < n_dofs; ++j)
                rhs(a, j) = deviatoric(n_dofs + a, j);
              for (unsigned int c = 0; c < n_p; ++c)
                rhs(a, n_dofs + c) = coupling(c, n_dofs + a);
            }
          K_aa.gauss_jordan();
          FullMatrix<double> G(n_a, n_dofs + n_p);
          multiply(G, K_aa, rhs);
          for (unsigned int a = 0; a < n_a; ++a)
            {
              for (unsigned int i = 0; i < n_dofs; ++i)
                for (unsigned int j = 0; j < n_dofs; ++j)
                  block.reduced(i, j) -= deviatoric(i, n_dofs + a) * G(a, j);
              for (unsigned int c = 0; c < n_p; ++c)
                {
                  const double B_ca = coupling(c, n_dofs + a);
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    block.coupling(c, j) -= B_ca * G(a, j);
                  for (unsigned int d = 0; d < n_p; ++d)
                    block.pressure(c, d) += B_ca * G(a, n_dofs + d);
                }
            }
        }
      block.mass          = mass;
      block.shear_modulus = mu;
    }
  } // namespace


  /// The integrals over the strain modes (shape functions, then the
  /// incompatible modes) that the cell matrix and load are made of.
  struct SmallStrainKernel::ModeIntegrals
  {
    ModeIntegrals(const unsigned int n_modes, const unsigned int n_p)
      : matrix(n_modes, n_modes)
      , mass(n_p, n_p)
      , coupling(n_p, n_modes)
      , growth_rhs(n_modes)
      , growth_moments(n_p, 0.)
    {}

    /// eps:C:eps + kappa div div (lower triangle; without the volumetric
    /// part where it is projected)
    FullMatrix<double> matrix;
    /// int q_a q_b and int q_a div(phi_i) of the pressure modes q
    FullMatrix<double> mass, coupling;
    /// the growth eigenstrain's load kappa g div(phi_i) (displacement
    /// formulation) and its moments int q_a g (projected)
    Vector<double>      growth_rhs;
    std::vector<double> growth_moments;
    bool                grows = false;
  };


  SmallStrainKernel::SmallStrainKernel(const ElasticityParameters &parameters,
                                       const Quadrature<3>        &quadrature,
                                       const LayerMaterials       &materials,
                                       const GrowthField          &growth)
    : parameters(parameters)
    , quadrature(quadrature)
    , materials(materials)
    , growth(growth)
  {}


  void
  SmallStrainKernel::integrate_modes(
    const DoFHandler<3>::active_cell_iterator &cell,
    const CellScratch                         &scratch,
    ModeIntegrals                             &integrals,
    Vector<double>                            &cell_rhs) const
  {
    const FEValues<3>               &fe_values = scratch.fe_values;
    const FiniteElement<3>          &fe        = fe_values.get_fe();
    const Material                  &material  = materials[cell->material_id()];
    const unsigned int               n_dofs    = fe.n_dofs_per_cell();
    const unsigned int               n_q       = fe_values.n_quadrature_points;
    const unsigned int               n_modes   = integrals.matrix.m();
    const unsigned int               n_p       = parameters.n_pressure_modes();
    const bool                       mixed     = n_p > 0;
    const bool                       enhanced  = n_modes > n_dofs;
    const FEValuesExtractors::Vector displacement(0);
    const SymmetricTensor<4, 3>      C     = material.small_strain_tangent();
    const double                     kappa = material.moduli().bulk_modulus;
    const PressureBasis              basis(mixed ? n_p : 1, cell);
    std::vector<double>              q_basis(n_p);
    std::vector<SymmetricTensor<2, 3>> eps(n_modes), C_eps(n_modes);
    std::vector<double>                div(n_modes);
    Vector<double>                     force(3);
    const Tensor<2, 3> J0 = enhanced ? centre_jacobian(cell) : Tensor<2, 3>();

    for (unsigned int q = 0; q < n_q; ++q)
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            eps[i] = fe_values[displacement].symmetric_gradient(i, q);
            div[i] = trace(eps[i]);
          }
        if (enhanced)
          {
            const auto g =
              incompatible_mode_gradients(J0,
                                          quadrature.point(q),
                                          JxW / quadrature.weight(q));
            for (unsigned int d = 0; d < 3; ++d)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  Tensor<2, 3> grad;
                  grad[c]                 = g[d];
                  eps[n_dofs + 3 * d + c] = symmetrize(grad);
                  div[n_dofs + 3 * d + c] = g[d][c];
                }
          }
        // eps:C:eps + kappa div div (the mixed formulations project the
        // divergence instead: B-bar)
        const double kappa_q = mixed ? 0. : kappa;
        const double g       = growth.at(cell, q);
        integrals.grows      = integrals.grows || g != 0.;
        for (unsigned int i = 0; i < n_modes; ++i)
          {
            C_eps[i] = C * eps[i];
            if (!mixed)
              integrals.growth_rhs(i) += kappa * g * div[i] * JxW;
          }
        for (unsigned int i = 0; i < n_modes; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            integrals.matrix(i, j) +=
              (C_eps[i] * eps[j] + kappa_q * div[i] * div[j]) * JxW;

        if (scratch.body_force != nullptr)
          {
            scratch.body_force->vector_value(fe_values.quadrature_point(q),
                                             force);
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                cell_rhs(i) += fe_values.shape_value(i, q) * force(c) * JxW;
              }
          }

        if (mixed)
          {
            basis.evaluate(fe_values.quadrature_point(q), q_basis);
            for (unsigned int a = 0; a < n_p; ++a)
              {
                for (unsigned int b = 0; b < n_p; ++b)
                  integrals.mass(a, b) += q_basis[a] * q_basis[b] * JxW;
                for (unsigned int i = 0; i < n_modes; ++i)
                  integrals.coupling(a, i) += q_basis[a] * div[i] * JxW;
                integrals.growth_moments[a] += q_basis[a] * g * JxW;
              }
          }
      }
    for (unsigned int i = 0; i < n_modes; ++i)
      for (unsigned int j = i + 1; j < n_modes; ++j)
        integrals.matrix(i, j) = integrals.matrix(j, i);
  }


  void
  SmallStrainKernel::assemble(const DoFHandler<3>::active_cell_iterator &cell,
                              const CellScratch &scratch,
                              CellCopy          &copy) const
  {
    FullMatrix<double> &cell_matrix = copy.matrix;
    Vector<double>     &cell_rhs    = copy.residual;
    const Material     &material    = materials[cell->material_id()];
    const unsigned int  n_dofs = scratch.fe_values.get_fe().n_dofs_per_cell();
    const bool enhanced = parameters.formulation == Formulation::enhanced;
    // the volumetric strain is projected unless n_p == 0
    const unsigned int n_p   = parameters.n_pressure_modes();
    const bool         mixed = n_p > 0;
    // the strain modes: the shape functions, then (enhanced) the nine
    // incompatible modes e_c P_d, condensed out at the end
    const unsigned int n_modes = n_dofs + (enhanced ? 9 : 0);
    Assert(cell_matrix.m() == n_dofs && cell_rhs.size() == n_dofs,
           ExcDimensionMismatch(cell_matrix.m(), n_dofs));
    const double kappa = material.moduli().bulk_modulus;

    cell_rhs = 0;
    ModeIntegrals integrals(n_modes, n_p);
    integrate_modes(cell, scratch, integrals, cell_rhs);
    FullMatrix<double> &matrix = integrals.matrix;

    Assert(!scratch.with_pressure || mixed,
           ExcMessage("A pressure block needs a pressure space."));
    if (scratch.with_pressure)
      pressure_block(matrix,
                     integrals.coupling,
                     integrals.mass,
                     kappa,
                     material.moduli().shear_modulus,
                     n_dofs,
                     copy.pressure);

    if (mixed)
      {
        // kappa B^T M^{-1} B: the bulk modulus on the projected divergence
        integrals.mass.gauss_jordan();
        FullMatrix<double> m_inv_b(n_p, n_modes);
        multiply(m_inv_b, integrals.mass, integrals.coupling);
        FullMatrix<double> volumetric(n_modes, n_modes);
        multiply(volumetric, integrals.coupling, m_inv_b, Transposed::left);
        matrix.add(kappa, volumetric);
        for (unsigned int i = 0; i < n_modes; ++i)
          for (unsigned int a = 0; a < n_p; ++a)
            integrals.growth_rhs(i) +=
              kappa * m_inv_b(a, i) * integrals.growth_moments[a];
      }
    if (!integrals.grows)
      integrals.growth_rhs = 0;

    if (enhanced)
      condense(matrix, integrals.growth_rhs, n_dofs, cell_matrix, cell_rhs);
    else
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          for (unsigned int j = 0; j < n_dofs; ++j)
            cell_matrix(i, j) = matrix(i, j);
          cell_rhs(i) += integrals.growth_rhs(i);
        }
  }
} // namespace ssc
