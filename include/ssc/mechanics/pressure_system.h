#ifndef ssc_mechanics_pressure_system_h
#define ssc_mechanics_pressure_system_h

#include <deal.II/base/index_set.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

#include <ssc/mechanics/cell_pressure_block.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The displacement-pressure saddle point of the mixed formulations,
   *   [K_0  B^T] [u]   [r]
   *   [B    -C ] [p] = [0],
   * whose displacement solves K u = r for the tangent K = K_0 + B^T C^{-1} B
   * that the other solvers use: the cells' CellPressureBlock, assembled.
   * The pressure lives on the locally owned cells, n_p modes each,
   * numbered cell by cell on each rank after the ranks before it; C and
   * the Schur approximation are block diagonal and stay with their cells.
   */
  class PressureSystem
  {
  public:
    /// The pressure of the locally owned cells of @p dof_handler, @p
    /// n_pressure_modes per cell.
    PressureSystem(const DoFHandler<3> &dof_handler,
                   const unsigned int   n_pressure_modes);

    /// K_0 with the sparsity of the tangent, B's sparsity from the cells
    /// with @p constraints on its displacement columns.
    void
    setup(const TrilinosWrappers::SparsityPattern &tangent_sparsity,
          const AffineConstraints<double>         &constraints);

    /// Zeroes K_0 and B before an assembly.
    void
    reset();

    /// Adds the block of @p cell (its displacement dofs @p dofs) with
    /// @p constraints and keeps its C and Schur approximation.
    void
    add_cell(const DoFHandler<3>::active_cell_iterator  &cell,
             const std::vector<types::global_dof_index> &dofs,
             const CellPressureBlock                    &block,
             const AffineConstraints<double>            &constraints);

    /// Adds a displacement-only block (a dof contribution) to K_0.
    void
    add_to_reduced(const std::vector<types::global_dof_index> &dofs,
                   const FullMatrix<double>                   &matrix,
                   const AffineConstraints<double>            &constraints);

    /// Ends an assembly.
    void
    compress();

    const TrilinosWrappers::SparseMatrix &
    reduced_matrix() const
    {
      return reduced;
    }

    const TrilinosWrappers::SparseMatrix &
    coupling_matrix() const
    {
      return coupling;
    }

    const IndexSet &
    locally_owned_pressure() const
    {
      return owned;
    }

    /// dst = C src.
    void
    apply_pressure_block(TrilinosWrappers::MPI::Vector       &dst,
                         const TrilinosWrappers::MPI::Vector &src) const;

    /// dst = S^{-1} src with S the cells' Schur approximations.
    void
    apply_schur_inverse(TrilinosWrappers::MPI::Vector       &dst,
                        const TrilinosWrappers::MPI::Vector &src) const;

  private:
    /// The global pressure indices of the locally owned @p cell.
    std::vector<types::global_dof_index>
    pressure_indices(const DoFHandler<3>::active_cell_iterator &cell) const;

    /// dst = blocks[cell] src cell by cell.
    void
    apply_blocks(const std::vector<FullMatrix<double>> &blocks,
                 TrilinosWrappers::MPI::Vector         &dst,
                 const TrilinosWrappers::MPI::Vector   &src) const;

    const DoFHandler<3> &dof_handler;
    const unsigned int   n_p;
    IndexSet             owned;
    /// First pressure index of each locally owned cell by active cell
    /// index (local numbering).
    std::vector<unsigned int>       first_of_cell;
    types::global_dof_index         offset = 0;
    std::vector<FullMatrix<double>> pressure_blocks, schur_inverses;
    TrilinosWrappers::SparseMatrix  reduced, coupling;
  };
} // namespace ssc

#endif
