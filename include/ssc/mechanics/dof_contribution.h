#ifndef ssc_mechanics_dof_contribution_h
#define ssc_mechanics_dof_contribution_h

#include <deal.II/base/types.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <utility>
#include <vector>

namespace ssc
{
  using namespace dealii;

  /**
   * Something that acts on a few individual dofs rather than on cells, e.g.
   * the contact of skin nodes with a rigid punch whose position is itself a
   * dof. The volume elasticity adds its couplings to the sparsity pattern
   * and its blocks to the Newton system, through the same constraints as
   * the cells.
   */
  class DofContribution
  {
  public:
    /// Receives one dense block: its dofs, tangent and residual (internal
    /// force minus load, ordered like the dofs).
    using BlockSink =
      std::function<void(const std::vector<types::global_dof_index> &,
                         const FullMatrix<double> &,
                         const Vector<double> &)>;

    virtual ~DofContribution() = default;

    /// Dofs beyond the mesh's locally relevant ones that this contribution
    /// reads or writes on this rank, with their displacement components
    /// (e.g. the two ends of a tie across a wound, which no cell shares).
    /// ElasticSystem::setup() makes them locally relevant. None by default.
    virtual std::vector<std::pair<types::global_dof_index, unsigned int>>
    extra_relevant_dofs() const
    {
      return {};
    }

    /// The dof groups that may form a block (those of this rank), for the
    /// sparsity pattern; called once the dofs and ties exist.
    virtual std::vector<std::vector<types::global_dof_index>>
    couplings() const = 0;

    /// The blocks at the (locally relevant) solution @p u; @p with_tangent
    /// false: only the residuals are needed.
    virtual void
    add_nonlinear(const TrilinosWrappers::MPI::Vector &u,
                  const bool                           with_tangent,
                  const BlockSink                     &add) const = 0;

    /// The (locally relevant) state @p u solves the load increment: see
    /// NonlinearProblem::accept_state() (collective). True by default.
    virtual bool
    accept(const TrilinosWrappers::MPI::Vector &u)
    {
      (void)u;
      return true;
    }

    /// The load increment is abandoned: back to the state of the last
    /// accept() that returned true. Nothing by default.
    virtual void
    reject()
    {}
  };
} // namespace ssc

#endif
