#ifndef ssc_mechanics_system_assembler_h
#define ssc_mechanics_system_assembler_h

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <vector>

#include <ssc/mechanics/cell_assembly_data.h>
#include <ssc/mechanics/cell_contribution.h>
#include <ssc/mechanics/cell_pressure_block.h>
#include <ssc/mechanics/displacement_field.h>
#include <ssc/mechanics/dof_contribution.h>
#include <ssc/mechanics/pressure_system.h>
#include <ssc/mechanics/volume_kernel.h>

namespace ssc
{
  /**
   * The one assembly loop of the mechanics (MeshWorker::mesh_loop over the
   * locally owned cells): every cell's residual and tangent come from the
   * VolumeKernel plus the attached cell contributions (embedded septa and
   * ligaments), then the dof contributions (punch contact) add their
   * blocks. The same loop serves the tangent with the right-hand side -r,
   * the residual alone, and reactions (the residual weighted by a field
   * that is one on a condition's dofs).
   */
  class SystemAssembler
  {
  public:
    SystemAssembler(const DisplacementField &field, const VolumeKernel &kernel);

    /// Adds @p contribution to every cell from now on; it must outlive
    /// this object's assemblies.
    void
    attach(const CellContribution &contribution);

    /// Adds @p contribution's blocks from now on (attach before the
    /// sparsity pattern is made).
    void
    attach(const DofContribution &contribution);

    /// Adds the couplings of the dof contributions to @p sparsity.
    void
    add_couplings(const AffineConstraints<double>   &constraints,
                  TrilinosWrappers::SparsityPattern &sparsity) const;

    /**
     * At the (ghosted) displacement @p u: -r into @p rhs and, with @p
     * matrix, the tangent into it, both distributed with @p constraints
     * (zeroed first); with @p pressure (and @p matrix) also the tangent's
     * displacement-pressure structure into it. Returns the number of
     * inverted cells on all ranks (their contributions are left out).
     */
    unsigned int
    assemble(const TrilinosWrappers::MPI::Vector &u,
             const AffineConstraints<double>     &constraints,
             const Function<3>                   *body_force,
             TrilinosWrappers::SparseMatrix      *matrix,
             TrilinosWrappers::MPI::Vector       &rhs,
             PressureSystem                      *pressure = nullptr) const;

    /**
     * The virtual work of the residual r(u) against the (ghosted) weight
     * @p w, per displacement component: sum_i r_i w_i over the dofs of
     * component c (@p component_of gives a dof's component for the dof
     * contributions). With w one on a condition's dofs this is the force
     * the body exerts on that condition (collective).
     */
    Tensor<1, 3>
    weighted_residual(const TrilinosWrappers::MPI::Vector &u,
                      const TrilinosWrappers::MPI::Vector &w,
                      const Function<3>                   *body_force,
                      const std::function<unsigned int(types::global_dof_index)>
                        &component_of) const;

  private:
    /// The cell's residual (and tangent) at @p u into @p data, the
    /// contributions included; a cell whose weight @p w (if given) vanishes
    /// is skipped.
    void
    cell_work(const DoFHandler<3>::active_cell_iterator &cell,
              CellScratch                               &scratch,
              CellCopy                                  &data,
              const TrilinosWrappers::MPI::Vector       &u,
              const TrilinosWrappers::MPI::Vector       *w) const;

    /// Runs the loop over the locally owned cells with @p copier.
    void
    loop(const TrilinosWrappers::MPI::Vector         &u,
         const TrilinosWrappers::MPI::Vector         *w,
         const Function<3>                           *body_force,
         const bool                                   with_matrix,
         const std::function<void(const CellCopy &)> &copier,
         const bool with_pressure = false) const;

    const DisplacementField              &field;
    const VolumeKernel                   &kernel;
    std::vector<const CellContribution *> cell_contributions;
    std::vector<const DofContribution *>  dof_contributions;
  };
} // namespace ssc

#endif
