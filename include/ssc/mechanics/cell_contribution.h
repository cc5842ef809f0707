#ifndef ssc_mechanics_cell_contribution_h
#define ssc_mechanics_cell_contribution_h

#include <deal.II/dofs/dof_handler.h>

#include <ssc/mechanics/cell_assembly_data.h>

namespace ssc
{
  using namespace dealii;

  /**
   * Something that adds stiffness (and load) to the background cells it
   * acts on, e.g. the septa and ligaments embedded in them. The system
   * assembler calls it from its one cell loop, so the tangent, the residual
   * and the reaction forces all include it.
   */
  class CellContribution
  {
  public:
    virtual ~CellContribution() = default;

    /**
     * Adds the tangent to @p copy.matrix (if @p scratch.with_matrix; it may
     * be left out when only the residual is wanted) and the internal force
     * minus the load to @p copy.residual, at the cell's displacement values
     * @p scratch.u, for the locally owned @p cell. @p scratch.kinematics is
     * that of the cell's own law: a contribution inside a small-strain cell
     * is linear too.
     */
    virtual void
    add_to_cell(const DoFHandler<3>::active_cell_iterator &cell,
                const CellScratch                         &scratch,
                CellCopy                                  &copy) const = 0;
  };
} // namespace ssc

#endif
