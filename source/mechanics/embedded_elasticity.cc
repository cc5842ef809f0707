#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <ssc/mechanics/embedded_elasticity.h>

#include <array>
#include <cmath>

namespace ssc
{
  EmbeddedElasticity::EmbeddedElasticity(
    const EmbeddedKind                                         kind,
    const std::vector<CellQuadrature>                         &quadrature,
    const std::function<EmbeddedMaterial(types::material_id)> &material,
    const FiniteElement<3>                                    &fe,
    const Mapping<3>                                          &mapping,
    const MPI_Comm                                             communicator,
    const bool                                                 tension_only)
    : kind(kind)
    , fe(fe)
    , mapping(mapping)
    , tension_only(tension_only)
  {
    unsigned int n_local = 0;
    for (const CellQuadrature &cell_quadrature : quadrature)
      {
        const unsigned int index = cell_quadrature.cell->active_cell_index();
        if (points_per_cell.size() <= index)
          points_per_cell.resize(
            cell_quadrature.cell->get_triangulation().n_active_cells());
        for (unsigned int q = 0; q < cell_quadrature.JxW.size(); ++q)
          {
            const EmbeddedMaterial m   = material(cell_quadrature.materials[q]);
            const double           JxW = cell_quadrature.JxW[q];
            LocalPoint             p;
            p.unit_point = cell_quadrature.unit_points[q];
            p.direction  = cell_quadrature.directions[q];
            if (kind == EmbeddedKind::membrane)
              {
                const double E = m.youngs_modulus, nu = m.poisson_ratio;
                p.first  = JxW * m.size * E * nu / (1. - nu * nu);
                p.second = JxW * m.size * E / (1. + nu);
              }
            else
              {
                p.first  = JxW * m.youngs_modulus * m.size;
                p.second = 0;
              }
            points_per_cell[index].push_back(p);
            ++n_local;
          }
      }
    n_global_points = Utilities::MPI::sum(n_local, communicator);
  }


  void
  EmbeddedElasticity::add_to_cell(
    const DoFHandler<3>::active_cell_iterator &cell,
    FullMatrix<double>                        &cell_matrix,
    Vector<double> &) const
  {
    const unsigned int index = cell->active_cell_index();
    if (index >= points_per_cell.size() || points_per_cell[index].empty())
      return;
    const std::vector<LocalPoint> &local         = points_per_cell[index];
    const auto                     fe_values_ptr = reinit_points(cell, local);
    const FEValues<3>             &fe_values     = *fe_values_ptr;

    const unsigned int        n = fe.n_dofs_per_cell();
    std::vector<Tensor<2, 3>> strain(n); // tangential part P eps P
    std::vector<double>       trace(n);
    for (unsigned int q = 0; q < local.size(); ++q)
      {
        const Tensor<1, 3> &d = local[q].direction;
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            const Tensor<1, 3> g = fe_values.shape_grad_component(i, q, c);
            if (kind == EmbeddedKind::cable)
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
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              double value = local[q].first * trace[i] * trace[j];
              if (kind == EmbeddedKind::membrane)
                value += local[q].second * scalar_product(strain[i], strain[j]);
              cell_matrix(i, j) += value;
            }
      }
  }


  std::unique_ptr<FEValues<3>>
  EmbeddedElasticity::reinit_points(
    const DoFHandler<3>::active_cell_iterator &cell,
    const std::vector<LocalPoint>             &local) const
  {
    std::vector<Point<3>> units(local.size());
    for (unsigned int q = 0; q < local.size(); ++q)
      units[q] = local[q].unit_point;
    auto fe_values = std::make_unique<FEValues<3>>(mapping,
                                                   fe,
                                                   Quadrature<3>(units),
                                                   update_gradients);
    fe_values->reinit(cell);
    return fe_values;
  }


  void
  EmbeddedElasticity::add_to_cell_nonlinear(
    const DoFHandler<3>::active_cell_iterator &cell,
    const Vector<double>                      &u,
    const bool                                 with_matrix,
    FullMatrix<double>                        &cell_matrix,
    Vector<double>                            &cell_residual) const
  {
    const unsigned int index = cell->active_cell_index();
    if (index >= points_per_cell.size() || points_per_cell[index].empty())
      return;
    const std::vector<LocalPoint> &local     = points_per_cell[index];
    const auto                     fe_values = reinit_points(cell, local);
    const unsigned int             n         = fe.n_dofs_per_cell();
    std::vector<unsigned int>      component(n);
    std::vector<Tensor<1, 3>>      g(n); // reference gradients
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe.system_to_component_index(i).first;
    for (unsigned int q = 0; q < local.size(); ++q)
      {
        Tensor<2, 3> F = unit_symmetric_tensor<3>();
        for (unsigned int i = 0; i < n; ++i)
          {
            g[i] = fe_values->shape_grad_component(i, q, component[i]);
            F[component[i]] += u(i) * g[i];
          }
        const Tensor<1, 3> &d = local[q].direction;
        if (kind == EmbeddedKind::cable)
          {
            // e = (|F tau|^2 - 1) / 2, S = E A e; de/du_i = a_ci (g_i . tau)
            const Tensor<1, 3>  a     = F * d;
            const double        e     = 0.5 * (a * a - 1.);
            const bool          slack = tension_only && e < 0;
            const double        S     = slack ? 0. : local[q].first * e;
            std::vector<double> de(n), gd(n);
            for (unsigned int i = 0; i < n; ++i)
              {
                gd[i] = g[i] * d;
                de[i] = a[component[i]] * gd[i];
                cell_residual(i) += S * de[i];
              }
            if (with_matrix)
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) +=
                    (slack ? 0. : local[q].first * de[i] * de[j]) +
                    (component[i] == component[j] ? S * gd[i] * gd[j] : 0.);
          }
        else
          {
            // E = (P F^T F P - P)/2, S = dW/dE (membrane_state());
            // dE_i = sym(a_i (x) b_i), a_i = P F^T e_ci, b_i = P g_i.
            // Strain variations lie in the tangent plane, whose symmetric
            // tensors form a space of dimension 3: in the basis
            // B_k = t1 t1, t2 t2, t1 t2 + t2 t1 (t1, t2 orthonormal in the
            // plane) dE_i has the coordinates v_i, S:dE_i = s.v_i with
            // s_k = S:B_k, and d2W[dE_i, dE_j] = v_i.D v_j with
            // D_kl = d2W[B_k, B_l]: the n^2 tangent entries cost a dot
            // product of 3-vectors each instead of tensor contractions.
            Tensor<2, 3> P = unit_symmetric_tensor<3>();
            P -= outer_product(d, d);
            const Tensor<2, 3>  E     = 0.5 * (P * transpose(F) * F * P - P);
            const Tensor<2, 3>  PFt   = P * transpose(F);
            const MembraneState state = membrane_state(E, P, local[q]);
            const auto [t1, t2]       = tangent_basis(d);
            const std::array<Tensor<2, 3>, 3> basis = {
              {outer_product(t1, t1),
               outer_product(t2, t2),
               outer_product(t1, t2) + outer_product(t2, t1)}};
            Tensor<1, 3> s;
            Tensor<2, 3> D;
            for (unsigned int k = 0; k < 3; ++k)
              {
                s[k] = scalar_product(state.stress, basis[k]);
                for (unsigned int l = 0; l < 3; ++l)
                  D[k][l] = state.second_derivative(basis[k], basis[l]);
              }
            std::vector<Tensor<1, 3>> v(n), Dv(n), b(n), Sb(n);
            for (unsigned int i = 0; i < n; ++i)
              {
                Tensor<1, 3> a;
                for (unsigned int k = 0; k < 3; ++k)
                  a[k] = PFt[k][component[i]];
                b[i]            = P * g[i];
                Sb[i]           = state.stress * b[i];
                const double a1 = a * t1, a2 = a * t2;
                const double b1 = b[i] * t1, b2 = b[i] * t2;
                v[i][0] = a1 * b1;
                v[i][1] = a2 * b2;
                v[i][2] = 0.5 * (a1 * b2 + a2 * b1);
                Dv[i]   = D * v[i];
                cell_residual(i) += s * v[i];
              }
            if (with_matrix)
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) +=
                    Dv[i] * v[j] +
                    (component[i] == component[j] ? b[j] * Sb[i] : 0.);
          }
      }
  }


  std::pair<Tensor<1, 3>, Tensor<1, 3>>
  EmbeddedElasticity::tangent_basis(const Tensor<1, 3> &normal)
  {
    // the coordinate axis least aligned with the normal, projected
    unsigned int axis = 0;
    for (unsigned int k = 1; k < 3; ++k)
      if (std::abs(normal[k]) < std::abs(normal[axis]))
        axis = k;
    Tensor<1, 3> t1 = -normal[axis] * normal;
    t1[axis] += 1.;
    t1 /= t1.norm();
    return {t1, cross_product_3d(normal, t1)};
  }


  EmbeddedElasticity::MembraneState
  EmbeddedElasticity::membrane_state(const Tensor<2, 3> &E,
                                     const Tensor<2, 3> &P,
                                     const LocalPoint   &point) const
  {
    // St Venant-Kirchhoff membrane: S = lambda_ps tr(E) P + 2 mu E, with
    // point.first = lambda_ps t JxW and point.second = 2 mu t JxW
    MembraneState state;
    state.lambda = point.first;
    state.two_mu = point.second;
    state.stress = point.first * trace(E) * P + point.second * E;
    if (!tension_only)
      return state;

    // Tension-field theory (Pipkin's relaxed energy): a membrane cannot
    // carry compression, it wrinkles. With the principal Green strains
    // E1 >= E2 of the tangent plane it is taut while the smaller principal
    // stress lambda E1 + (lambda + 2 mu) E2 is positive, wrinkled (uniaxial
    // tension E_Y E1 along n1, W = E_Y E1^2 / 2) while E1 > 0, and slack
    // otherwise. The relaxed energy is C^1 and its stress positive
    // semi-definite; so is its consistent tangent (the material part in
    // second_derivative() and the geometric part b.S b are both >= 0).
    const auto principal = eigenvectors(symmetrize(E)); // descending
    // the normal direction of the membrane is an eigenvector of E with
    // eigenvalue 0: keep the two tangential pairs
    std::array<std::pair<double, Tensor<1, 3>>, 2> in_plane;
    unsigned int                                   n_in_plane = 0;
    {
      // the eigenvector most aligned with the normal is dropped
      unsigned int normal = 0;
      double       best   = -1;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const double alignment =
            (principal[k].second - P * principal[k].second).norm_square();
          if (alignment > best)
            {
              best   = alignment;
              normal = k;
            }
        }
      for (unsigned int k = 0; k < 3; ++k)
        if (k != normal)
          in_plane[n_in_plane++] = principal[k];
    }
    const double E1 = in_plane[0].first, E2 = in_plane[1].first;
    // ">=": the undeformed membrane (E = 0, where the relaxed energy has
    // a kink) gets the taut stiffness, so the first Newton step from rest
    // sees the septa
    if (point.first * E1 + (point.first + point.second) * E2 >= 0)
      return state; // taut
    state.regime = E1 > 0 ? MembraneRegime::wrinkled : MembraneRegime::slack;
    state.stress = Tensor<2, 3>();
    if (state.regime == MembraneRegime::slack)
      return state;
    state.youngs = point.second * (2 * point.first + point.second) /
                   (point.first + point.second);
    state.n1     = in_plane[0].second;
    state.n2     = in_plane[1].second;
    state.E1     = E1;
    state.E2     = E2;
    state.stress = state.youngs * E1 * outer_product(state.n1, state.n1);
    return state;
  }


  double
  EmbeddedElasticity::MembraneState::second_derivative(
    const Tensor<2, 3> &A,
    const Tensor<2, 3> &B) const
  {
    switch (regime)
      {
        case MembraneRegime::taut:
          return lambda * trace(A) * trace(B) + two_mu * scalar_product(A, B);
        case MembraneRegime::slack:
          return 0;
        case MembraneRegime::wrinkled:
          // W = E_Y E1^2 / 2: d2W = E_Y (dE1)^2 + E_Y E1 d2E1, with
          // dE1 = n1.A n1 and d2E1 = 2 (n1.A n2)(n1.B n2) / (E1 - E2)
          return youngs *
                 ((n1 * (A * n1)) * (n1 * (B * n1)) +
                  2 * E1 * (n1 * (A * n2)) * (n1 * (B * n2)) / (E1 - E2));
      }
    return 0;
  }


  double
  EmbeddedElasticity::axial_or_membrane_stress(
    const SymmetricTensor<2, 3> &strain,
    const Tensor<1, 3>          &d,
    const EmbeddedMaterial      &m) const
  {
    const Tensor<2, 3> eps = strain;
    if (kind == EmbeddedKind::cable)
      return m.youngs_modulus * (d * (eps * d));
    // von Mises stress of the plane-stress state sigma = lambda_ps tr P +
    // 2 mu e in the tangent plane
    Tensor<2, 3> P = unit_symmetric_tensor<3>();
    P -= outer_product(d, d);
    const Tensor<2, 3> e = P * eps * P;
    const double       E = m.youngs_modulus, nu = m.poisson_ratio;
    const Tensor<2, 3> sigma =
      E * nu / (1 - nu * nu) * trace(e) * P + E / (1 + nu) * e;
    const Tensor<2, 3> s =
      sigma - trace(sigma) / 3. * unit_symmetric_tensor<3>();
    return std::sqrt(1.5 * scalar_product(s, s));
  }
} // namespace ssc
