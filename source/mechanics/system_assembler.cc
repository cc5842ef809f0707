#include <deal.II/base/mpi.h>

#include <deal.II/grid/filtered_iterator.h>

#include <deal.II/meshworker/mesh_loop.h>

#include <cmath>

#include <ssc/mechanics/system_assembler.h>

namespace ssc
{
  SystemAssembler::SystemAssembler(const DisplacementField &field,
                                   const VolumeKernel      &kernel)
    : field(field)
    , kernel(kernel)
  {}


  void
  SystemAssembler::attach(const CellContribution &contribution)
  {
    cell_contributions.push_back(&contribution);
  }


  void
  SystemAssembler::attach(const DofContribution &contribution)
  {
    dof_contributions.push_back(&contribution);
  }


  void
  SystemAssembler::add_couplings(
    const AffineConstraints<double>   &constraints,
    TrilinosWrappers::SparsityPattern &sparsity) const
  {
    for (const DofContribution *contribution : dof_contributions)
      for (const auto &group : contribution->couplings())
        constraints.add_entries_local_to_global(group, sparsity, false);
  }


  void
  SystemAssembler::cell_work(const DoFHandler<3>::active_cell_iterator &cell,
                             CellScratch                               &scratch,
                             CellCopy                                  &data,
                             const TrilinosWrappers::MPI::Vector       &u,
                             const TrilinosWrappers::MPI::Vector       *w) const
  {
    const unsigned int n = field.fe().n_dofs_per_cell();
    data.reinit(cell, n);
    if (w != nullptr)
      {
        cell->get_dof_values(*w, scratch.w);
        if (scratch.w.linfty_norm() == 0.)
          {
            data.skipped = true;
            return;
          }
      }
    cell->get_dof_indices(data.dofs);
    cell->get_dof_values(u, scratch.u);
    CellPressureBlock *const block =
      scratch.with_pressure ? &data.pressure : nullptr;
    if (!kernel.assemble(cell, scratch, data))
      {
        data.inverted = true;
        return;
      }
    // the contributions (embedded septa, ligaments) belong to K_0: they
    // are what the cell matrix gains beyond the volume's
    const bool contributions_to_reduced =
      block != nullptr && !cell_contributions.empty();
    FullMatrix<double> volume_matrix;
    if (contributions_to_reduced)
      volume_matrix = data.matrix;
    for (const CellContribution *contribution : cell_contributions)
      contribution->add_to_cell(cell, scratch, data);
    if (contributions_to_reduced)
      {
        block->reduced.add(1., data.matrix);
        block->reduced.add(-1., volume_matrix);
      }
    if (block != nullptr)
      block->augment();
    AssertDimension(data.matrix.m(), n);
    AssertDimension(data.residual.size(), n);
#ifdef DEBUG
    // every law and contribution derives from an energy: the cell tangent
    // is its Hessian, so it must be symmetric
    if (scratch.with_matrix)
      {
        const double scale = data.matrix.linfty_norm();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < i; ++j)
            Assert(std::abs(data.matrix(i, j) - data.matrix(j, i)) <=
                     1e-8 * scale,
                   ExcMessage("The cell tangent is not symmetric."));
      }
#endif
    if (w != nullptr)
      for (unsigned int i = 0; i < n; ++i)
        data.residual(i) *= scratch.w(i);
  }


  void
  SystemAssembler::loop(const TrilinosWrappers::MPI::Vector &u,
                        const TrilinosWrappers::MPI::Vector *w,
                        const Function<3>                   *body_force,
                        const bool                           with_matrix,
                        const std::function<void(const CellCopy &)> &copier,
                        const bool with_pressure) const
  {
    CellScratch sample(field.mapping(),
                       field.fe(),
                       kernel.quadrature(),
                       VolumeKernel::update_flags());
    sample.body_force    = body_force;
    sample.with_matrix   = with_matrix;
    sample.with_pressure = with_pressure;
    using Iterator       = DoFHandler<3>::active_cell_iterator;
    // only the locally owned cells: mesh_loop calls the copier for every
    // cell of its range, also where it skips the worker, and would hand it
    // the copy data of an earlier cell
    MeshWorker::mesh_loop(
      filter_iterators(field.dof_handler().active_cell_iterators(),
                       IteratorFilters::LocallyOwnedCell()),
      [&](const Iterator &cell, CellScratch &scratch, CellCopy &data) {
        cell_work(cell, scratch, data, u, w);
      },
      copier,
      sample,
      CellCopy(),
      MeshWorker::assemble_own_cells);
  }


  unsigned int
  SystemAssembler::assemble(const TrilinosWrappers::MPI::Vector &u,
                            const AffineConstraints<double>     &constraints,
                            const Function<3>                   *body_force,
                            TrilinosWrappers::SparseMatrix      *matrix,
                            TrilinosWrappers::MPI::Vector       &rhs,
                            PressureSystem                      *pressure) const
  {
    if (matrix == nullptr)
      pressure = nullptr;
    if (matrix != nullptr)
      *matrix = 0;
    if (pressure != nullptr)
      pressure->reset();
    rhs                   = 0;
    unsigned int inverted = 0;
    // adds a block (tangent, residual r) as -r to the right-hand side
    const auto add_block = [&](const std::vector<types::global_dof_index> &dofs,
                               const FullMatrix<double> &block_matrix,
                               const Vector<double>     &block_residual) {
      Vector<double> minus_r(block_residual);
      minus_r *= -1.;
      if (matrix != nullptr)
        constraints.distribute_local_to_global(
          block_matrix, minus_r, dofs, *matrix, rhs);
      else
        constraints.distribute_local_to_global(minus_r, dofs, rhs);
    };
    loop(
      u,
      nullptr,
      body_force,
      matrix != nullptr,
      [&](const CellCopy &data) {
        if (data.inverted)
          ++inverted;
        else
          {
            add_block(data.dofs, data.matrix, data.residual);
            if (pressure != nullptr)
              pressure->add_cell(data.cell,
                                 data.dofs,
                                 data.pressure,
                                 constraints);
          }
      },
      pressure != nullptr);
    // the dof contributions (punch contact) are displacement-only: K_0
    for (const DofContribution *contribution : dof_contributions)
      contribution->add_nonlinear(
        u,
        matrix != nullptr,
        [&](const std::vector<types::global_dof_index> &dofs,
            const FullMatrix<double>                   &block_matrix,
            const Vector<double>                       &block_residual) {
          add_block(dofs, block_matrix, block_residual);
          if (pressure != nullptr)
            pressure->add_to_reduced(dofs, block_matrix, constraints);
        });
    if (matrix != nullptr)
      matrix->compress(VectorOperation::add);
    if (pressure != nullptr)
      pressure->compress();
    rhs.compress(VectorOperation::add);
    return Utilities::MPI::sum(inverted, u.get_mpi_communicator());
  }


  Tensor<1, 3>
  SystemAssembler::weighted_residual(
    const TrilinosWrappers::MPI::Vector                        &u,
    const TrilinosWrappers::MPI::Vector                        &w,
    const Function<3>                                          *body_force,
    const std::function<unsigned int(types::global_dof_index)> &component_of)
    const
  {
    const FiniteElement<3> &fe = field.fe();
    Tensor<1, 3>            force;
    loop(u, &w, body_force, false, [&](const CellCopy &data) {
      if (data.skipped || data.inverted)
        return;
      for (unsigned int i = 0; i < data.dofs.size(); ++i)
        force[fe.system_to_component_index(i).first] += data.residual(i);
    });
    // the blocks' residuals on the weighted dofs (e.g. contact forces on
    // the punch), by the component of each dof
    for (const DofContribution *contribution : dof_contributions)
      contribution->add_nonlinear(
        u,
        false,
        [&](const std::vector<types::global_dof_index> &dofs,
            const FullMatrix<double> &,
            const Vector<double> &residual) {
          for (unsigned int k = 0; k < dofs.size(); ++k)
            force[component_of(dofs[k])] += residual(k) * w[dofs[k]];
        });
    return Utilities::MPI::sum(force, u.get_mpi_communicator());
  }
} // namespace ssc
