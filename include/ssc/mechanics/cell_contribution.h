#ifndef ssc_mechanics_cell_contribution_h
#define ssc_mechanics_cell_contribution_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace ssc
{
  using namespace dealii;

  /**
   * Something that adds stiffness (and load) to the background cells it
   * acts on, e.g. the septa and ligaments embedded in them. The volume
   * elasticity calls it from its one cell assembly, so matrix, right-hand
   * side and the residual behind the reaction forces all include it.
   */
  class CellContribution
  {
  public:
    virtual ~CellContribution() = default;

    /// Adds to @p cell_matrix and @p cell_rhs (ordered like the cell's
    /// dofs) what this contribution puts on the locally owned @p cell.
    virtual void
    add_to_cell(const DoFHandler<3>::active_cell_iterator &cell,
                FullMatrix<double>                        &cell_matrix,
                Vector<double>                            &cell_rhs) const = 0;

    /**
     * For Newton's method: adds the tangent to @p cell_matrix (if
     * @p with_matrix; it may be left out when only the residual is wanted)
     * and the internal force minus the load to @p cell_residual, at the
     * cell's displacement values @p cell_displacement. The default is the
     * linear response K u - f of add_to_cell(); finite-strain contributions
     * override it.
     */
    virtual void
    add_to_cell_nonlinear(const DoFHandler<3>::active_cell_iterator &cell,
                          const Vector<double> &cell_displacement,
                          const bool            with_matrix,
                          FullMatrix<double>   &cell_matrix,
                          Vector<double>       &cell_residual) const
    {
      FullMatrix<double> K(cell_matrix.m(), cell_matrix.n());
      Vector<double>     f(cell_residual.size());
      add_to_cell(cell, K, f);
      K.vmult_add(cell_residual, cell_displacement);
      cell_residual -= f;
      if (with_matrix)
        cell_matrix.add(1., K);
    }
  };
} // namespace ssc

#endif
