#ifndef ssc_multigrid_geometric_multigrid_preconditioner_h
#define ssc_multigrid_geometric_multigrid_preconditioner_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <memory>

namespace ssc
{
  using namespace dealii;

  /**
   * A geometric multigrid V-cycle for the displacement system, as the
   * preconditioner of CG: the mesh's refinement levels, Galerkin level
   * matrices P^T A P of the assembled matrix (so that embedded septa and
   * ligaments, contact and friction, which live in the fine matrix only,
   * reach every level), Chebyshev smoothing (degree 4) on the exact inverse
   * of each level's vertical line blocks, and a sparse direct solve on the
   * coarsest level.
   *
   * Why: the layered punch's thin layers make flat cells, on which point
   * smoothers and ML's AMG need 100-1,500 iterations that grow with every
   * refinement; the line-smoothed V-cycle needs 6-30, flat over three
   * refinements, nu up to 0.49, a layer contrast of 1:1000, Q1 and Q2, and
   * at 295k DoFs it is 8 times faster than the Cholesky factor
   * (benchmarks/multigrid_layered).
   *
   * Needs a mesh of uniform refinements of a coarse mesh (Mesh/Global
   * refinements >= 1, no local refinement), so that every active cell is on
   * the finest level. Runs on any number of MPI ranks: the finest level is
   * the distributed tangent itself (not copied), the coarser levels are
   * Trilinos matrices (their Galerkin products computed by EpetraExt), the
   * line blocks are each rank's parts of the lines (BackgroundMesh orders
   * its coarse cells column by column so that p4est's partition cuts few
   * lines), and the coarsest level is solved by MUMPS's L D L^T factor
   * (distributed, its symbolic analysis kept across tangents: 40 % less
   * solve time than Amesos's KLU on the forearm scene). The
   * constrained DoFs of the update (Dirichlet conditions, ties) are kept
   * out of the coarse corrections: their rows of the finest prolongation
   * are zero.
   */
  class GeometricMultigridPreconditioner
    : public TrilinosWrappers::PreconditionBase
  {
  public:
    /// A V-cycle on the mesh of @p dof_handler, whose numbering the
    /// matrices and vectors use.
    explicit GeometricMultigridPreconditioner(const DoFHandler<3> &dof_handler);

    ~GeometricMultigridPreconditioner() override;

    /// Refuses a mesh without refinement levels or with local refinement,
    /// naming the mesh parameters.
    static void
    require_uniform_refinements(const Triangulation<3> &tria);

    /// Builds the V-cycle for @p matrix with the constrained DoFs of
    /// @p constraints. Returns false, keeping no V-cycle, if a line block
    /// of a level matrix is not positive definite (a tangent past a
    /// stability limit).
    bool
    initialize(const TrilinosWrappers::SparseMatrix &matrix,
               const AffineConstraints<double>      &constraints);

    /// Whether a V-cycle is ready.
    bool
    initialized() const;

    /// Number of levels of the hierarchy (0 before the first initialize()).
    unsigned int
    n_levels() const;

    /// Drops the V-cycle.
    void
    clear();

  private:
    class VCycle;
    const DoFHandler<3>    &field_dofs;
    std::shared_ptr<VCycle> cycle;
  };
} // namespace ssc

#endif
