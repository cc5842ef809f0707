#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <array>
#include <cmath>

#include <ssc/mechanics/embedded_stiffness.h>

namespace ssc
{
  EmbeddedStiffness::EmbeddedStiffness(
    const std::vector<CellQuadrature> &quadrature,
    const MembraneLaw                 &law,
    const FiniteElement<3>            &fe,
    const Mapping<3>                  &mapping,
    const MPI_Comm                     communicator)
    : membrane(law)
    , fe(fe)
  {
    setup_points(quadrature, mapping, communicator);
  }


  EmbeddedStiffness::EmbeddedStiffness(
    const std::vector<CellQuadrature> &quadrature,
    const CableLaw                    &law,
    const FiniteElement<3>            &fe,
    const Mapping<3>                  &mapping,
    const MPI_Comm                     communicator)
    : cable(law)
    , fe(fe)
  {
    setup_points(quadrature, mapping, communicator);
  }


  void
  EmbeddedStiffness::setup_points(const std::vector<CellQuadrature> &quadrature,
                                  const Mapping<3>                  &mapping,
                                  const MPI_Comm communicator)
  {
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto [c, alpha] = fe.system_to_component_index(i);
        component.push_back(c);
        base.push_back(alpha);
      }
    const unsigned int n_base  = fe.base_element(0).n_dofs_per_cell();
    unsigned int       n_local = 0;
    for (const CellQuadrature &cell_quadrature : quadrature)
      {
        const unsigned int index = cell_quadrature.cell->active_cell_index();
        if (points_per_cell.size() <= index)
          points_per_cell.resize(
            cell_quadrature.cell->get_triangulation().n_active_cells());
        FEValues<3> fe_values(mapping,
                              fe,
                              Quadrature<3>(cell_quadrature.unit_points),
                              update_gradients);
        fe_values.reinit(cell_quadrature.cell);
        for (unsigned int q = 0; q < cell_quadrature.JxW.size(); ++q)
          {
            std::vector<Tensor<1, 3>> gradients(n_base);
            for (unsigned int alpha = 0; alpha < n_base; ++alpha)
              gradients[alpha] = fe_values.shape_grad_component(
                fe.component_to_system_index(0, alpha), q, 0);
            LocalPoint point{cell_quadrature.directions[q],
                             cell_quadrature.JxW[q],
                             cell_quadrature.materials[q],
                             0.,
                             std::move(gradients)};
            points_per_cell[index].push_back(std::move(point));
            ++n_local;
          }
      }
    n_global_points = Utilities::MPI::sum(n_local, communicator);
  }


  void
  EmbeddedStiffness::grow_with(
    const GrowthField                                     &growth_field,
    const std::function<double(const types::material_id)> &weight,
    const double                                           follow)
  {
    AssertThrow(membrane.has_value(),
                ExcMessage("Only membranes grow with the material."));
    growth        = &growth_field;
    growth_follow = follow;
    for (std::vector<LocalPoint> &local : points_per_cell)
      for (LocalPoint &point : local)
        point.growth_weight = weight(point.material);
  }


  double
  EmbeddedStiffness::growth_ratio(const double weight) const
  {
    return growth == nullptr ? 0. : growth_follow * growth->scale() * weight;
  }


  double
  EmbeddedStiffness::growth_stretch_square(const double weight) const
  {
    const double volume_ratio = 1. + growth_ratio(weight);
    AssertThrow(volume_ratio > 0,
                ExcMessage("A septum's growth shrinks it to nothing."));
    return std::cbrt(volume_ratio * volume_ratio);
  }


  void
  EmbeddedStiffness::add_to_cell(
    const DoFHandler<3>::active_cell_iterator &cell,
    const CellScratch                         &scratch,
    CellCopy                                  &copy) const
  {
    const Vector<double> &u             = scratch.u;
    const bool            with_matrix   = scratch.with_matrix;
    FullMatrix<double>   &cell_matrix   = copy.matrix;
    Vector<double>       &cell_residual = copy.residual;
    const unsigned int    index         = cell->active_cell_index();
    if (index >= points_per_cell.size() || points_per_cell[index].empty())
      return;
    const std::vector<LocalPoint> &local = points_per_cell[index];
    AssertDimension(u.size(), fe.n_dofs_per_cell());
    if (scratch.kinematics == Kinematics::small_strain)
      add_linear(local, u, cell_matrix, cell_residual);
    else if (cable)
      add_cable(local, u, with_matrix, cell_matrix, cell_residual);
    else
      add_membrane(local, u, with_matrix, cell_matrix, cell_residual);
  }


  void
  EmbeddedStiffness::add_linear(const std::vector<LocalPoint> &local,
                                const Vector<double>          &u,
                                FullMatrix<double>            &cell_matrix,
                                Vector<double> &cell_residual) const
  {
    // membrane: (t/2) (lambda_ps (P:eps)^2 + 2 mu (P eps P):(P eps P));
    // cable: (E A / 2) (tau . eps tau)^2
    const auto [t_lambda, t_two_mu] = membrane ?
                                        membrane->small_strain_coefficients() :
                                        std::make_pair(cable->stiffness(), 0.);
    const unsigned int        n     = fe.n_dofs_per_cell();
    std::vector<Tensor<2, 3>> strain(n); // tangential part P eps P
    std::vector<double>       trace(n);
    FullMatrix<double>        K(n, n);
    for (unsigned int q = 0; q < local.size(); ++q)
      {
        const Tensor<1, 3> &d = local[q].direction;
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int  c = component[i];
            const Tensor<1, 3> &g = local[q].base_gradients[base[i]];
            if (cable)
              // tau . eps tau with eps = sym(e_c (x) g)
              trace[i] = d[c] * (d * g);
            else
              {
                // P eps P = sym((P e_c) (x) (P g))
                Tensor<1, 3> Pe = -d[c] * d;
                Pe[c] += 1.;
                const Tensor<1, 3> Pg = g - (d * g) * d;
                const Tensor<2, 3> a  = outer_product(Pe, Pg);
                strain[i]             = 0.5 * (a + transpose(a));
                trace[i]              = Pe * Pg;
              }
          }
        const double first  = local[q].JxW * t_lambda;
        const double second = local[q].JxW * t_two_mu;
        if (membrane && growth != nullptr)
          {
            // the eigenstrain e P, e = (lambda_g^3 - 1) / 3, adds
            // -e (2 t lambda_ps + 2 t mu) P:d eps to the residual
            const double e = growth_ratio(local[q].growth_weight) / 3.;
            for (unsigned int i = 0; i < n; ++i)
              cell_residual(i) -= e * (2. * first + second) * trace[i];
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              double value = first * trace[i] * trace[j];
              if (membrane)
                value += second * scalar_product(strain[i], strain[j]);
              K(i, j) += value;
            }
      }
    // K u - f: the embedded structures carry no load of their own
    K.vmult_add(cell_residual, u);
    cell_matrix.add(1., K);
  }


  Tensor<2, 3>
  EmbeddedStiffness::deformation_gradient(
    const LocalPoint          &point,
    const Vector<double>      &u,
    std::vector<Tensor<1, 3>> &gradients) const
  {
    Tensor<2, 3> F = unit_symmetric_tensor<3>();
    for (unsigned int i = 0; i < component.size(); ++i)
      {
        gradients[i] = point.base_gradients[base[i]];
        F[component[i]] += u(i) * gradients[i];
      }
    return F;
  }


  void
  EmbeddedStiffness::add_cable(const std::vector<LocalPoint> &local,
                               const Vector<double>          &u,
                               const bool                     with_matrix,
                               FullMatrix<double>            &cell_matrix,
                               Vector<double> &cell_residual) const
  {
    const unsigned int        n = fe.n_dofs_per_cell();
    std::vector<Tensor<1, 3>> g(n); // reference gradients
    std::vector<double>       de(n), gd(n);
    for (unsigned int q = 0; q < local.size(); ++q)
      {
        const Tensor<2, 3> F = deformation_gradient(local[q], u, g);
        // e = (|F tau|^2 / lambda_0^2 - 1) / 2, S = E A e;
        // de/du_i = a_ci (g_i . tau) / lambda_0^2 =: s a_ci (g_i . tau)
        const Tensor<1, 3> &d = local[q].direction;
        const Tensor<1, 3>  a = F * d;
        const double        e = cable->strain(a * a);
        const double        s = cable->strain_scale();
        const double        S = local[q].JxW * cable->axial_force(e);
        const double        k =
          cable->slack(e) ? 0. : local[q].JxW * cable->stiffness();
        for (unsigned int i = 0; i < n; ++i)
          {
            gd[i] = g[i] * d;
            de[i] = s * a[component[i]] * gd[i];
            cell_residual(i) += S * de[i];
          }
        if (with_matrix)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              cell_matrix(i, j) +=
                k * de[i] * de[j] +
                (component[i] == component[j] ? s * S * gd[i] * gd[j] : 0.);
      }
  }


  void
  EmbeddedStiffness::add_membrane(const std::vector<LocalPoint> &local,
                                  const Vector<double>          &u,
                                  const bool                     with_matrix,
                                  FullMatrix<double>            &cell_matrix,
                                  Vector<double> &cell_residual) const
  {
    const unsigned int        n = fe.n_dofs_per_cell();
    std::vector<Tensor<1, 3>> g(n); // reference gradients
    std::vector<Tensor<1, 3>> v(n), Dv(n), b(n), Sb(n);
    for (unsigned int q = 0; q < local.size(); ++q)
      {
        const Tensor<2, 3> F = deformation_gradient(local[q], u, g);
        // E = (P F^T F P - P)/2, S = dW/dE (MembraneLaw::state());
        // dE_i = sym(a_i (x) b_i), a_i = P F^T e_ci, b_i = P g_i.
        // Strain variations lie in the tangent plane, whose symmetric
        // tensors form a space of dimension 3: in the basis
        // B_k = t1 t1, t2 t2, t1 t2 + t2 t1 (t1, t2 orthonormal in the
        // plane) dE_i has the coordinates v_i, S:dE_i = s.v_i with
        // s_k = S:B_k, and d2W[dE_i, dE_j] = v_i.D v_j with
        // D_kl = d2W[B_k, B_l]: the n^2 tangent entries cost a dot
        // product of 3-vectors each instead of tensor contractions.
        const Tensor<1, 3> &d = local[q].direction;
        Tensor<2, 3>        P = unit_symmetric_tensor<3>();
        P -= outer_product(d, d);
        // A grown membrane (grow_with()) is stress-free at P C P =
        // lambda_g^2 P: its energy lambda_g^2 W(E_e), E_e = (P C P /
        // lambda_g^2 - P) / 2, has dW/dE = S(E_e) and d2W/dE2 =
        // D(E_e) / lambda_g^2.
        const double stretch2 = growth_stretch_square(local[q].growth_weight);
        const Tensor<2, 3> E  = 0.5 * (P * transpose(F) * F * P / stretch2 - P);
        const Tensor<2, 3> PFt         = P * transpose(F);
        const MembraneLaw::State state = membrane->state(E, P, local[q].JxW);
        const auto [t1, t2]            = MembraneLaw::tangent_basis(d);
        const std::array<Tensor<2, 3>, 3> basis = {
          {outer_product(t1, t1),
           outer_product(t2, t2),
           outer_product(t1, t2) + outer_product(t2, t1)}};
        Tensor<1, 3> s;
        Tensor<2, 3> D;
        for (unsigned int k = 0; k < 3; ++k)
          {
            s[k] = scalar_product(state.stress, basis[k]);
            if (with_matrix)
              for (unsigned int l = 0; l < 3; ++l)
                D[k][l] =
                  state.second_derivative(basis[k], basis[l]) / stretch2;
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            Tensor<1, 3> a;
            for (unsigned int k = 0; k < 3; ++k)
              a[k] = PFt[k][component[i]];
            b[i]            = P * g[i];
            const double a1 = a * t1, a2 = a * t2;
            const double b1 = b[i] * t1, b2 = b[i] * t2;
            v[i][0] = a1 * b1;
            v[i][1] = a2 * b2;
            v[i][2] = 0.5 * (a1 * b2 + a2 * b1);
            cell_residual(i) += s * v[i];
          }
        if (!with_matrix)
          continue;
        for (unsigned int i = 0; i < n; ++i)
          {
            Dv[i] = D * v[i];
            Sb[i] = state.stress * b[i];
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            cell_matrix(i, j) +=
              Dv[i] * v[j] + (component[i] == component[j] ? b[j] * Sb[i] : 0.);
      }
  }
} // namespace ssc
