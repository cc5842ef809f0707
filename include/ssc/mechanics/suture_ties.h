#ifndef ssc_mechanics_suture_ties_h
#define ssc_mechanics_suture_ties_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

#include <ssc/mechanics/dof_contribution.h>

namespace ssc
{
  /// A mesh vertex a suture grips: its reference position, the dofs of its
  /// three displacement components and its share of the bite (the weights
  /// of one side of a suture sum to 1).
  struct SutureAnchor
  {
    Point<3>                               X;
    std::array<types::global_dof_index, 3> dofs;
    double                                 weight = 0;
  };

  /// One interrupted suture: the two bites it draws together, each the
  /// patch of the wound's wall it grips on one side (@p a, @p b), and its
  /// station, the reference position along the wound, mm.
  struct Suture
  {
    double                    station = 0;
    std::vector<SutureAnchor> a, b;
  };

  /**
   * Sutures that close a wound: each is a linear spring of stiffness k
   * between the mean positions of its two bites, x_a = sum_i w_i x_i over
   * the anchors of side a (likewise b), whose rest vector shrinks from their
   * separation when the closure starts (start()) to zero as the closure
   * fraction t goes from 0 to 1 (set_fraction()):
   * f = k ((x_a - x_b) - (1 - t) d_0), w_i f on each anchor of a and
   * -w_i f on each of b. The tangent k g g^T (g_i = +-w_i, per component)
   * is constant. A bite of finite size makes the suture's force a property
   * of the tissue, not of the mesh: a tie of single vertices would need
   * less force on every finer mesh (a point constraint of a 3D continuum
   * has no stiffness). At t = 1 the bites stay apart by |f| / k (penalty),
   * which residual_gap() reports.
   *
   * Every rank keeps every suture; the two bites share no cell, so their
   * dofs are made locally relevant everywhere (extra_relevant_dofs()) and
   * each suture is assembled by the rank that owns its first dof.
   */
  class SutureTies : public DofContribution
  {
  public:
    SutureTies(std::vector<Suture> sutures,
               const double        stiffness,
               const IndexSet     &locally_owned_dofs);

    std::vector<std::pair<types::global_dof_index, unsigned int>>
    extra_relevant_dofs() const override;

    std::vector<std::vector<types::global_dof_index>>
    couplings() const override;

    void
    add_nonlinear(const TrilinosWrappers::MPI::Vector &u,
                  const bool                           with_tangent,
                  const BlockSink                     &add) const override;

    /// Starts the closure from the (locally relevant) state @p u: the
    /// separations it draws to zero. Before it the ties exert nothing.
    void
    start(const TrilinosWrappers::MPI::Vector &u);

    /// The closure fraction t in [0, 1].
    void
    set_fraction(const double t)
    {
      fraction = t;
    }

    /// The force each suture pulls its positive lip with at @p u (the sum
    /// over its ties), N, by suture.
    std::vector<Tensor<1, 3>>
    forces(const TrilinosWrappers::MPI::Vector &u) const;

    /// The largest distance between the two bites' mean positions at @p u,
    /// mm.
    double
    residual_gap(const TrilinosWrappers::MPI::Vector &u) const;

    const std::vector<Suture> &
    sutures() const
    {
      return all_sutures;
    }

  private:
    /// The separation x_a - x_b of suture @p suture's bites at @p u.
    Tensor<1, 3>
    separation(const Suture                        &suture,
               const TrilinosWrappers::MPI::Vector &u) const;

    /// The spring force on bite a of suture @p s at @p u.
    Tensor<1, 3>
    force(const unsigned int s, const TrilinosWrappers::MPI::Vector &u) const;

    std::vector<Suture>       all_sutures;
    double                    stiffness;
    IndexSet                  owned;
    std::vector<Tensor<1, 3>> initial_separation;
    bool                      started  = false;
    double                    fraction = 0;
  };
} // namespace ssc

#endif
