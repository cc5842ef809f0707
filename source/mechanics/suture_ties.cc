#include <deal.II/base/exceptions.h>

#include <cmath>

#include <ssc/mechanics/suture_ties.h>

namespace ssc
{
  SutureTies::SutureTies(std::vector<Suture> sutures,
                         const double        stiffness,
                         const IndexSet     &locally_owned_dofs)
    : all_sutures(std::move(sutures))
    , stiffness(stiffness)
    , owned(locally_owned_dofs)
  {
    AssertThrow(stiffness > 0,
                ExcMessage("A suture's stiffness must be positive."));
    for (const Suture &suture : all_sutures)
      for (const auto *bite : {&suture.a, &suture.b})
        {
          double total = 0;
          for (const SutureAnchor &anchor : *bite)
            total += anchor.weight;
          AssertThrow(!bite->empty() && std::abs(total - 1.) < 1e-12,
                      ExcMessage("A suture's bite grips no vertex, or its "
                                 "weights do not sum to 1."));
        }
  }


  std::vector<std::pair<types::global_dof_index, unsigned int>>
  SutureTies::extra_relevant_dofs() const
  {
    std::vector<std::pair<types::global_dof_index, unsigned int>> dofs;
    for (const Suture &suture : all_sutures)
      for (const auto *bite : {&suture.a, &suture.b})
        for (const SutureAnchor &anchor : *bite)
          for (unsigned int d = 0; d < 3; ++d)
            dofs.emplace_back(anchor.dofs[d], d);
    return dofs;
  }


  namespace
  {
    /// The dofs of @p suture's anchors (a, then b; three per anchor) and
    /// their signed weights g.
    std::pair<std::vector<types::global_dof_index>, std::vector<double>>
    dofs_and_weights(const Suture &suture)
    {
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  g;
      for (const auto &[bite, sign] :
           {std::make_pair(&suture.a, 1.), std::make_pair(&suture.b, -1.)})
        for (const SutureAnchor &anchor : *bite)
          for (unsigned int d = 0; d < 3; ++d)
            {
              dofs.push_back(anchor.dofs[d]);
              g.push_back(sign * anchor.weight);
            }
      return {dofs, g};
    }
  } // namespace


  std::vector<std::vector<types::global_dof_index>>
  SutureTies::couplings() const
  {
    std::vector<std::vector<types::global_dof_index>> groups;
    for (const Suture &suture : all_sutures)
      if (owned.is_element(suture.a.front().dofs[0]))
        groups.push_back(dofs_and_weights(suture).first);
    return groups;
  }


  Tensor<1, 3>
  SutureTies::separation(const Suture                        &suture,
                         const TrilinosWrappers::MPI::Vector &u) const
  {
    Tensor<1, 3> d;
    for (const auto &[bite, sign] :
         {std::make_pair(&suture.a, 1.), std::make_pair(&suture.b, -1.)})
      for (const SutureAnchor &anchor : *bite)
        for (unsigned int c = 0; c < 3; ++c)
          d[c] += sign * anchor.weight * (anchor.X[c] + u[anchor.dofs[c]]);
    return d;
  }


  Tensor<1, 3>
  SutureTies::force(const unsigned int                   s,
                    const TrilinosWrappers::MPI::Vector &u) const
  {
    if (!started)
      return Tensor<1, 3>();
    return stiffness * (separation(all_sutures[s], u) -
                        (1. - fraction) * initial_separation[s]);
  }


  void
  SutureTies::add_nonlinear(const TrilinosWrappers::MPI::Vector &u,
                            const bool                           with_tangent,
                            const BlockSink                     &add) const
  {
    if (!started)
      return;
    for (unsigned int s = 0; s < all_sutures.size(); ++s)
      {
        const Suture &suture = all_sutures[s];
        if (!owned.is_element(suture.a.front().dofs[0]))
          continue;
        const auto [dofs, g] = dofs_and_weights(suture);
        const unsigned int n = dofs.size();
        const Tensor<1, 3> f = force(s, u);
        Vector<double>     residual(n);
        FullMatrix<double> matrix(n, n);
        // dof k is component k % 3 of its anchor
        for (unsigned int i = 0; i < n; ++i)
          {
            residual(i) = g[i] * f[i % 3];
            if (with_tangent)
              for (unsigned int j = i % 3; j < n; j += 3)
                matrix(i, j) = stiffness * g[i] * g[j];
          }
        add(dofs, matrix, residual);
      }
  }


  void
  SutureTies::start(const TrilinosWrappers::MPI::Vector &u)
  {
    initial_separation.clear();
    for (const Suture &suture : all_sutures)
      initial_separation.push_back(separation(suture, u));
    started  = true;
    fraction = 0;
  }


  std::vector<Tensor<1, 3>>
  SutureTies::forces(const TrilinosWrappers::MPI::Vector &u) const
  {
    std::vector<Tensor<1, 3>> result;
    for (unsigned int s = 0; s < all_sutures.size(); ++s)
      result.push_back(-force(s, u));
    return result;
  }


  double
  SutureTies::residual_gap(const TrilinosWrappers::MPI::Vector &u) const
  {
    double gap = 0;
    for (const Suture &suture : all_sutures)
      gap = std::max(gap, separation(suture, u).norm());
    return gap;
  }
} // namespace ssc
