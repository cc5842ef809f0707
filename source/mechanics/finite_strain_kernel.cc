#include <deal.II/base/symmetric_tensor.h>

#include <array>

#include <ssc/linear_algebra/cell_matrix_product.h>
#include <ssc/mechanics/finite_strain_kernel.h>
#include <ssc/mechanics/pressure_basis.h>

namespace ssc
{
  /// The projected dilatation of the mixed formulations on one cell: the
  /// pressure space's Gram matrix M (weighted by gamma) and its inverse,
  /// the coefficients of theta and of the pressure, and the tangent
  /// factor M^{-1} H M^{-1}.
  struct FiniteStrainKernel::ProjectedDilatation
  {
    FullMatrix<double>               mass, volumetric; // M, H
    FullMatrix<double>               mass_inverse;
    Vector<double>                   theta, pressure;
    FullMatrix<double>               stiffness;
    std::vector<std::vector<double>> basis; // [q][a]
  };


  FiniteStrainKernel::FiniteStrainKernel(const ElasticityParameters &parameters,
                                         const LayerMaterials       &materials,
                                         const GrowthField          &growth,
                                         QuadratureHistory          &history)
    : parameters(parameters)
    , materials(materials)
    , growth(growth)
    , history(history)
  {}


  bool
  FiniteStrainKernel::deformation_gradients(
    const DoFHandler<3>::active_cell_iterator &cell,
    const CellScratch                         &scratch,
    std::vector<Tensor<2, 3>>                 &F,
    std::vector<double>                       &gamma) const
  {
    const FEValues<3>      &fe_values = scratch.fe_values;
    const FiniteElement<3> &fe        = fe_values.get_fe();
    const unsigned int      n         = fe.n_dofs_per_cell();
    const unsigned int      n_q       = fe_values.n_quadrature_points;
    const Vector<double>   &u         = scratch.u;
    AssertDimension(u.size(), n);
    F.assign(n_q, unit_symmetric_tensor<3>());
    gamma.resize(n_q);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            F[q][c] += u(i) * fe_values.shape_grad_component(i, q, c);
          }
        if (!(determinant(F[q]) > 0))
          return false;
        gamma[q] = 1. + growth.at(cell, q);
      }
    return true;
  }


  bool
  FiniteStrainKernel::project_dilatation(
    const DoFHandler<3>::active_cell_iterator &cell,
    const CellScratch                         &scratch,
    const std::vector<Tensor<2, 3>>           &F,
    const std::vector<double>                 &gamma,
    ProjectedDilatation                       &projection) const
  {
    const FEValues<3>      &fe_values = scratch.fe_values;
    const VolumetricEnergy &volumetric =
      materials[cell->material_id()].volumetric();
    const unsigned int  n_q = fe_values.n_quadrature_points;
    const unsigned int  n_p = parameters.n_pressure_modes();
    const PressureBasis basis(n_p, cell);
    projection.basis.resize(n_q);
    FullMatrix<double> mass(n_p, n_p);
    Vector<double>     moments(n_p); // int q_a J
    for (unsigned int q = 0; q < n_q; ++q)
      {
        basis.evaluate(fe_values.quadrature_point(q), projection.basis[q]);
        const auto  &b   = projection.basis[q];
        const double JxW = fe_values.JxW(q);
        for (unsigned int a = 0; a < n_p; ++a)
          {
            for (unsigned int c = 0; c < n_p; ++c)
              mass(a, c) += gamma[q] * b[a] * b[c] * JxW;
            moments(a) += b[a] * determinant(F[q]) * JxW;
          }
      }
    projection.mass = mass;
    projection.mass_inverse.reinit(n_p, n_p);
    projection.mass_inverse.invert(mass);
    projection.theta.reinit(n_p);
    projection.mass_inverse.vmult(projection.theta, moments);
    Vector<double>     pressure_moments(n_p);
    FullMatrix<double> H(n_p, n_p);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const auto &b     = projection.basis[q];
        double      theta = 0;
        for (unsigned int a = 0; a < n_p; ++a)
          theta += projection.theta(a) * b[a];
        if (!(theta > 0))
          return false;
        const double JxW = fe_values.JxW(q);
        for (unsigned int a = 0; a < n_p; ++a)
          {
            pressure_moments(a) +=
              gamma[q] * volumetric.pressure(theta) * b[a] * JxW;
            for (unsigned int c = 0; c < n_p; ++c)
              H(a, c) += gamma[q] * volumetric.pressure_derivative(theta) *
                         b[a] * b[c] * JxW;
          }
      }
    projection.volumetric = H;
    projection.pressure.reinit(n_p);
    projection.mass_inverse.vmult(projection.pressure, pressure_moments);
    // M^{-1} H M^{-1}
    FullMatrix<double> H_M_inverse(n_p, n_p);
    multiply(H_M_inverse, H, projection.mass_inverse);
    projection.stiffness.reinit(n_p, n_p);
    multiply(projection.stiffness, projection.mass_inverse, H_M_inverse);
    return true;
  }


  void
  FiniteStrainKernel::integrate(const DoFHandler<3>::active_cell_iterator &cell,
                                const CellScratch               &scratch,
                                const std::vector<Tensor<2, 3>> &F,
                                const std::vector<double>       &gamma,
                                const ProjectedDilatation       &projection,
                                FullMatrix<double>              &B,
                                CellCopy                        &copy) const
  {
    const FEValues<3>      &fe_values     = scratch.fe_values;
    const FiniteElement<3> &fe            = fe_values.get_fe();
    const Material         &material      = materials[cell->material_id()];
    const VolumetricEnergy &volumetric    = material.volumetric();
    const Function<3>      *body_force    = scratch.body_force;
    const bool              with_matrix   = scratch.with_matrix;
    FullMatrix<double>     &cell_matrix   = copy.matrix;
    Vector<double>         &cell_residual = copy.residual;
    const unsigned int      n             = fe.n_dofs_per_cell();
    const unsigned int      n_q           = fe_values.n_quadrature_points;
    const unsigned int      n_p           = parameters.n_pressure_modes();
    const bool              projected     = n_p > 0;
    // share of U(J) at the quadrature points (stabilises the projection)
    const double beta = projected ? parameters.volumetric_stabilisation : 1.;

    cell_matrix   = 0;
    cell_residual = 0;
    // The tangent couples dof i = (component c, base function alpha) and
    // dof j = (d, beta) by g_alpha[k] T[c][k][d][l] g_beta[l] with the
    // spatial shape gradients g and one spatial tangent T per quadrature
    // point (material, geometric and volumetric parts), so it is assembled
    // by blocks of base functions: W = g_alpha . T once per base function,
    // then a dot product of 3-vectors per entry.
    const unsigned int n_base = fe.base_element(0).n_dofs_per_cell();
    std::vector<std::array<unsigned int, 3>> dof_of(n_base);
    std::vector<unsigned int>                component(n), base(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto [c, alpha] = fe.system_to_component_index(i);
        component[i]          = c;
        base[i]               = alpha;
        dof_of[alpha][c]      = i;
      }
    std::vector<Tensor<1, 3>>         g(n_base); // spatial shape gradients
    std::vector<Tensor<3, 3>>         W(n_base);
    SymmetricTensor<2, 3>             tau;
    Tensor<4, 3>                      T;
    Vector<double>                    force(3);
    std::vector<MaterialPointHistory> point_history;
    if (material.n_history_variables() > 0)
      point_history = history.points(cell);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const double       JxW   = fe_values.JxW(q);
        const double       J     = determinant(F[q]);
        const Tensor<2, 3> F_inv = invert(F[q]);
        // Growth F_g = gamma^{1/3} I with the energy gamma W(F_e), F_e =
        // F F_g^{-1}: the isochoric part at F_e, its stress and spatial
        // tangent scaled by gamma; the volumetric part sees J_e = J / gamma.
        const Tensor<2, 3> F_e = elastic_part(F[q], gamma[q]);
        const Point<3>    &X   = fe_values.quadrature_point(q);
        if (!point_history.empty())
          {
            if (with_matrix)
              material.isochoric_response_in_step(
                X, F_e, point_history[q], tau, T);
            else
              tau = material.isochoric_stress_in_step(X, F_e, point_history[q]);
          }
        else if (with_matrix)
          material.isochoric_response(X, F_e, tau, T);
        else
          tau = material.isochoric_stress(X, F_e);
        if (with_matrix)
          T *= gamma[q];
        tau *= gamma[q];
        const double J_e = J / gamma[q];
        double       p   = beta * volumetric.pressure(J_e);
        if (projected)
          for (unsigned int a = 0; a < n_p; ++a)
            p += (1. - beta) * projection.pressure(a) * projection.basis[q][a];
        for (unsigned int alpha = 0; alpha < n_base; ++alpha)
          g[alpha] = transpose(F_inv) *
                     fe_values.shape_grad_component(dof_of[alpha][0], q, 0);
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int ci  = component[i];
            const double       div = g[base[i]][ci];
            cell_residual(i) += ((tau * g[base[i]])[ci] + p * J * div) * JxW;
            if (with_matrix)
              for (unsigned int a = 0; a < n_p; ++a)
                B(a, i) += projection.basis[q][a] * J * div * JxW;
          }
        if (body_force != nullptr)
          {
            body_force->vector_value(fe_values.quadrature_point(q), force);
            for (unsigned int i = 0; i < n; ++i)
              cell_residual(i) -=
                fe_values.shape_value(i, q) * force(component[i]) * JxW;
          }
        if (!with_matrix)
          continue;

        // the volumetric part: p J (div_i div_j - g_i[cj] g_j[ci]) and the
        // point share of U''
        const double volumetric_point =
          beta * J * J * volumetric.pressure_derivative(J_e) / gamma[q];
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int d = 0; d < 3; ++d)
            {
              T[c][c][d][d] += p * J + volumetric_point;
              T[c][d][d][c] -= p * J;
            }
        T *= JxW;
        for (unsigned int row = 0; row < n_base; ++row)
          for (unsigned int c = 0; c < 3; ++c)
            W[row][c] = g[row] * T[c]; // [d][l]
        for (unsigned int row = 0; row < n_base; ++row)
          for (unsigned int column = 0; column < n_base; ++column)
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int d = 0; d < 3; ++d)
                cell_matrix(dof_of[row][c], dof_of[column][d]) +=
                  W[row][c][d] * g[column];
      }
  }


  void
  FiniteStrainKernel::add_projected_volumetric(
    const DoFHandler<3>::active_cell_iterator &cell,
    const CellScratch                         &scratch,
    const ProjectedDilatation                 &projection,
    const FullMatrix<double>                  &B,
    CellCopy                                  &copy) const
  {
    const unsigned int n           = copy.matrix.m();
    const unsigned int n_p         = parameters.n_pressure_modes();
    const bool         projected   = n_p > 0;
    const bool         with_matrix = scratch.with_matrix;
    const double beta = projected ? parameters.volumetric_stabilisation : 1.;
    FullMatrix<double> &cell_matrix = copy.matrix;
    CellPressureBlock *block = scratch.with_pressure ? &copy.pressure : nullptr;
    Assert(block == nullptr || (projected && with_matrix && beta < 1.),
           ExcMessage("A pressure block needs the projected dilatation."));
    if (block != nullptr)
      {
        // K_0: all but the condensed volumetric part; C = M H^{-1} M /
        // (1 - beta), so that B^T C^{-1} B is that part
        block->reduced  = cell_matrix;
        block->coupling = B;
        FullMatrix<double> H_inverse(n_p, n_p), H_inverse_M(n_p, n_p);
        H_inverse.invert(projection.volumetric);
        multiply(H_inverse_M, H_inverse, projection.mass);
        block->pressure.reinit(n_p, n_p);
        multiply(block->pressure, projection.mass, H_inverse_M);
        block->pressure *= 1. / (1. - beta);
        block->mass = projection.mass;
        block->shear_modulus =
          materials[cell->material_id()].moduli().shear_modulus;
      }
    if (projected && with_matrix && beta < 1.)
      {
        // (1 - beta) B^T M^{-1} H M^{-1} B
        FullMatrix<double> SB(n_p, n);
        multiply(SB, projection.stiffness, B);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              double value = 0;
              for (unsigned int a = 0; a < n_p; ++a)
                value += B(a, i) * SB(a, j);
              cell_matrix(i, j) += (1. - beta) * value;
            }
      }
  }


  bool
  FiniteStrainKernel::assemble(const DoFHandler<3>::active_cell_iterator &cell,
                               const CellScratch &scratch,
                               CellCopy          &copy) const
  {
    std::vector<Tensor<2, 3>> F;
    std::vector<double>       gamma;
    if (!deformation_gradients(cell, scratch, F, gamma))
      return false;
    ProjectedDilatation projection;
    const unsigned int  n_p = parameters.n_pressure_modes();
    if (n_p > 0 && !project_dilatation(cell, scratch, F, gamma, projection))
      return false;
    // int q_a J div(phi_i)
    FullMatrix<double> B(n_p, scratch.fe_values.get_fe().n_dofs_per_cell());
    integrate(cell, scratch, F, gamma, projection, B, copy);
    add_projected_volumetric(cell, scratch, projection, B, copy);
    return true;
  }
} // namespace ssc
