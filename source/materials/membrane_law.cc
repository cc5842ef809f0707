#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <ssc/materials/membrane_law.h>

namespace ssc
{
  MembraneLaw::MembraneLaw(const IsotropicModuli &moduli,
                           const double           thickness,
                           const bool             tension_field)
    : thickness(thickness)
    , t_lambda(thickness * moduli.plane_stress_lambda)
    , t_two_mu(thickness * 2. * moduli.shear_modulus)
    , tension_field(tension_field)
  {
    AssertThrow(thickness > 0, ExcMessage("A membrane needs a thickness."));
  }


  std::pair<Tensor<1, 3>, Tensor<1, 3>>
  MembraneLaw::tangent_basis(const Tensor<1, 3> &normal)
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


  MembraneLaw::State
  MembraneLaw::state(const Tensor<2, 3> &E,
                     const Tensor<2, 3> &P,
                     const double        weight) const
  {
    // St Venant-Kirchhoff membrane: S = lambda_ps tr(E) P + 2 mu E
    State state;
    state.lambda = weight * t_lambda;
    state.two_mu = weight * t_two_mu;
    state.stress = state.lambda * trace(E) * P + state.two_mu * E;
    if (!tension_field)
      return state;

    // Tension-field theory (Pipkin's relaxed energy): with the principal
    // Green strains E1 >= E2 of the tangent plane the membrane is taut
    // while the smaller principal stress lambda E1 + (lambda + 2 mu) E2 is
    // positive, wrinkled (uniaxial tension E_Y E1 along n1, W = E_Y E1^2 /
    // 2) while E1 > 0, and slack otherwise. The relaxed energy is C^1 and
    // its stress positive semi-definite; so is its consistent tangent (the
    // material part in second_derivative() and the geometric part b.S b of
    // the stiffness are both >= 0).
    {
      // E n = 0, so the principal strains of the plane follow from tr(E)
      // and E:E; most points are taut, and need no eigenvectors
      const double t = trace(E);
      const double root =
        std::sqrt(std::max(2. * scalar_product(E, E) - t * t, 0.));
      if (state.lambda * (t + root) / 2. +
            (state.lambda + state.two_mu) * (t - root) / 2. >=
          0)
        return state;
    }
    const auto principal = eigenvectors(symmetrize(E)); // descending
    // the normal of the membrane is an eigenvector of E with eigenvalue 0:
    // drop the eigenvector most aligned with it
    std::array<std::pair<double, Tensor<1, 3>>, 2> in_plane;
    {
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
      unsigned int n = 0;
      for (unsigned int k = 0; k < 3; ++k)
        if (k != normal)
          in_plane[n++] = principal[k];
    }
    const double E1 = in_plane[0].first, E2 = in_plane[1].first;
    // ">=": the undeformed membrane (E = 0, where the relaxed energy has a
    // kink) gets the taut stiffness, so the first Newton step from rest
    // sees the septa
    if (state.lambda * E1 + (state.lambda + state.two_mu) * E2 >= 0)
      return state;
    state.regime = E1 > 0 ? Regime::wrinkled : Regime::slack;
    state.stress = Tensor<2, 3>();
    if (state.regime == Regime::slack)
      return state;
    state.youngs = state.two_mu * (2 * state.lambda + state.two_mu) /
                   (state.lambda + state.two_mu);
    state.n1     = in_plane[0].second;
    state.n2     = in_plane[1].second;
    state.E1     = E1;
    state.E2     = E2;
    state.stress = state.youngs * E1 * outer_product(state.n1, state.n1);
    return state;
  }


  double
  MembraneLaw::State::second_derivative(const Tensor<2, 3> &A,
                                        const Tensor<2, 3> &B) const
  {
    switch (regime)
      {
        case Regime::taut:
          return lambda * trace(A) * trace(B) + two_mu * scalar_product(A, B);
        case Regime::slack:
          return 0;
        case Regime::wrinkled:
          // W = E_Y E1^2 / 2: d2W = E_Y (dE1)^2 + E_Y E1 d2E1, with
          // dE1 = n1.A n1 and d2E1 = 2 (n1.A n2)(n1.B n2) / (E1 - E2)
          return youngs *
                 ((n1 * (A * n1)) * (n1 * (B * n1)) +
                  2 * E1 * (n1 * (A * n2)) * (n1 * (B * n2)) / (E1 - E2));
      }
    return 0;
  }


  double
  MembraneLaw::von_mises_stress(const Tensor<2, 3> &F,
                                const Tensor<1, 3> &normal,
                                const Kinematics    kinematics) const
  {
    Tensor<2, 3> P = unit_symmetric_tensor<3>();
    P -= outer_product(normal, normal);
    if (kinematics == Kinematics::small_strain)
      {
        // sigma = lambda_ps tr(e) P + 2 mu e, e = P eps P
        const Tensor<2, 3> e =
          P * Tensor<2, 3>(symmetrize(F - unit_symmetric_tensor<3>())) * P;
        return von_mises(
          symmetrize((t_lambda * trace(e) * P + t_two_mu * e) / thickness));
      }
    const Tensor<2, 3> E = 0.5 * (P * transpose(F) * F * P - P);
    const State        s = state(E, P, 1. / thickness);
    // area stretch |cof(F) n| = J |F^{-T} n|
    const double J_s = determinant(F) * (transpose(invert(F)) * normal).norm();
    const Tensor<2, 3> sigma = F * s.stress * transpose(F) / J_s;
    return von_mises(symmetrize(sigma));
  }
} // namespace ssc
