#ifndef ssc_contact_punch_friction_h
#define ssc_contact_punch_friction_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <array>
#include <functional>
#include <vector>

#include <ssc/mechanics/dof_contribution.h>

namespace ssc
{
  /// How the skin nodes under the punch stand with respect to friction.
  struct FrictionState
  {
    unsigned int sticking = 0; ///< within the Coulomb cone
    unsigned int slipping = 0; ///< on it
    unsigned int free     = 0; ///< not pressed (normal force <= 0)
    /// The force of the skin on the punch in x and y (N, the model's).
    Tensor<1, 2> tangential_force;
    /// The sum of the normal forces used (N, the model's).
    double normal_force = 0;
  };

  /**
   * Coulomb friction between a rigid flat punch and the skin nodes it holds
   * vertically (the tie of the frictionless punch), regularised by a stick
   * stiffness: each node i is tied to a stick point a_i on the punch by the
   * energy
   * @f[
   *   \psi_i(d) = \begin{cases} \frac{k_i}{2}|d|^2 & |d| \le c_i/k_i \\
   *               c_i |d| - \frac{c_i^2}{2 k_i} & \text{otherwise}
   *               \end{cases},\qquad d = u_{xy} - a_i - s,\quad
   *   c_i = \mu N_i,
   * @f]
   * s the punch's lateral offset and N_i the node's normal force. Its
   * gradient is the return-mapped friction force: k_i d while the node
   * sticks, mu N_i d/|d| once it slips (backward Euler of the regularised
   * Coulomb law). With the stick points and normal forces frozen during a
   * load increment the energy is convex and C^1, the tangent symmetric
   * positive semi-definite, so Newton's method and its line search see an
   * energy as everywhere else. After each converged solve (accept()) the
   * normal forces become the tie's reactions at the nodes; if they moved by
   * more than 2 % (summed over the nodes), the increment is solved again
   * with them (a staggered fixed point, at most 8 passes), else the stick
   * points of slipping nodes move with them and the next increment starts.
   *
   * k_i = (penalty factor) E/h times the node's share of the surface area
   * (the integral of its shape function), h the face size and E the top
   * layer's modulus: a node sticks until it has slipped about 1/(penalty
   * factor) of a cell at a shear traction E.
   */
  class PunchFriction : public DofContribution
  {
  public:
    /**
     * The locally owned skin nodes (boundary @p top) for which @p held is
     * true (those the punch holds vertically); @p nodal_residual gives the
     * residual at every dof (ElasticSystem::nodal_residual()), whose
     * vertical entries are the nodes' normal forces (collective).
     */
    PunchFriction(
      const double                                   coefficient,
      const double                                   penalty_factor,
      const double                                   youngs_modulus,
      const DoFHandler<3>                           &dof_handler,
      const Mapping<3>                              &mapping,
      const types::boundary_id                       top,
      const std::function<bool(const Point<3> &)>   &held,
      std::function<TrilinosWrappers::MPI::Vector()> nodal_residual);

    std::vector<std::vector<types::global_dof_index>>
    couplings() const override;

    void
    add_nonlinear(const TrilinosWrappers::MPI::Vector &u,
                  const bool                           with_tangent,
                  const BlockSink                     &add) const override;

    /// Takes the normal forces from the tie's reactions at @p u; if they
    /// have settled, moves the stick points of slipping nodes and returns
    /// true, else returns false to have the increment solved again
    /// (collective).
    bool
    accept(const TrilinosWrappers::MPI::Vector &u) override;

    /// Back to the normal forces of the last accepted increment, with the
    /// passes counted afresh: an increment that was cut must not start
    /// from the normal forces of the larger one, nor with fewer passes.
    void
    reject() override;

    /// Moves the punch sideways to @p offset (x, y, mm) from where it
    /// first touched the skin.
    void
    set_offset(const Tensor<1, 2> &offset);

    /// The nodes' state in the last accepted increment, with the normal
    /// forces it was solved with (before accept() updated them).
    const FrictionState &
    accepted_state() const
    {
      return last_state;
    }

    /// Nodes on all ranks (collective).
    unsigned int
    n_nodes() const;

    /// Sum of the stick stiffnesses k_i (N/mm, the model's; collective).
    double
    total_stiffness() const;

  private:
    /// A skin node under the punch: its x, y and z dofs, stick stiffness,
    /// normal force and stick point.
    struct Node
    {
      std::array<types::global_dof_index, 3> dofs;
      double                                 stiffness    = 0;
      double                                 normal_force = 0;
      /// the normal force the last accepted increment handed on
      double       accepted_normal_force = 0;
      Tensor<1, 2> stick_point;
    };

    /// The node's slip from its stick point at @p u.
    Tensor<1, 2>
    slip(const Node &node, const TrilinosWrappers::MPI::Vector &u) const;

    /// The friction force on the node (the energy's gradient) at slip
    /// @p d, and whether it slips.
    std::pair<Tensor<1, 2>, bool>
    force(const Node &node, const Tensor<1, 2> &d) const;

    /// Relative change of the normal forces (summed over the nodes) below
    /// which they count as settled, and the most solves of one increment.
    static constexpr double       settled_change = 0.02;
    static constexpr unsigned int max_passes     = 8;

    const double                                   coefficient;
    std::function<TrilinosWrappers::MPI::Vector()> nodal_residual;
    MPI_Comm                                       mpi_communicator;
    std::vector<Node>                              nodes;
    Tensor<1, 2>                                   offset;
    FrictionState                                  last_state;
    /// solves of the current increment so far
    unsigned int passes = 0;
  };
} // namespace ssc

#endif
