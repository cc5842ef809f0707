#include <deal.II/base/mpi.h>

#include <deal.II/meshworker/mesh_loop.h>

#include <ssc/mechanics/system_assembler.h>

namespace ssc
{
  namespace
  {
    /// Per-thread scratch of the assembly loop: FEValues and the cell's
    /// displacement and weight values.
    struct AssemblyScratch
    {
      AssemblyScratch(const Mapping<3>       &mapping,
                      const FiniteElement<3> &fe,
                      const Quadrature<3>    &quadrature,
                      const UpdateFlags       flags)
        : fe_values(mapping, fe, quadrature, flags)
        , u(fe.n_dofs_per_cell())
        , w(fe.n_dofs_per_cell())
      {}

      AssemblyScratch(const AssemblyScratch &other)
        : fe_values(other.fe_values.get_mapping(),
                    other.fe_values.get_fe(),
                    other.fe_values.get_quadrature(),
                    other.fe_values.get_update_flags())
        , u(other.u.size())
        , w(other.w.size())
      {}

      FEValues<3>    fe_values;
      Vector<double> u, w;
    };
  } // namespace


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


  template <typename ScratchData>
  void
  SystemAssembler::cell_work(const DoFHandler<3>::active_cell_iterator &cell,
                             ScratchData                               &scratch,
                             CellData                                  &data,
                             const TrilinosWrappers::MPI::Vector       &u,
                             const TrilinosWrappers::MPI::Vector       *w,
                             const Function<3> *body_force,
                             const bool         with_matrix) const
  {
    const unsigned int n = field.fe().n_dofs_per_cell();
    data.matrix.reinit(n, n);
    data.residual.reinit(n);
    data.dofs.resize(n);
    data.inverted = false;
    data.skipped  = false;
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
    if (!kernel.residual_and_tangent(cell,
                                     scratch.fe_values,
                                     scratch.u,
                                     body_force,
                                     with_matrix,
                                     data.matrix,
                                     data.residual))
      {
        data.inverted = true;
        return;
      }
    const Kinematics kinematics = kernel.material(cell).kinematics();
    for (const CellContribution *contribution : cell_contributions)
      contribution->add_to_cell(
        cell, scratch.u, kinematics, with_matrix, data.matrix, data.residual);
    if (w != nullptr)
      for (unsigned int i = 0; i < n; ++i)
        data.residual(i) *= scratch.w(i);
  }


  void
  SystemAssembler::loop(
    const TrilinosWrappers::MPI::Vector         &u,
    const TrilinosWrappers::MPI::Vector         *w,
    const Function<3>                           *body_force,
    const bool                                   with_matrix,
    const std::function<void(const CellData &)> &copier) const
  {
    const AssemblyScratch sample(field.mapping(),
                                 field.fe(),
                                 kernel.quadrature(),
                                 VolumeKernel::update_flags());
    using Iterator = DoFHandler<3>::active_cell_iterator;
    MeshWorker::mesh_loop(
      field.dof_handler().begin_active(),
      Iterator(field.dof_handler().end()),
      [&](const Iterator &cell, AssemblyScratch &scratch, CellData &data) {
        cell_work(cell, scratch, data, u, w, body_force, with_matrix);
      },
      copier,
      sample,
      CellData(),
      MeshWorker::assemble_own_cells);
  }


  unsigned int
  SystemAssembler::assemble(const TrilinosWrappers::MPI::Vector &u,
                            const AffineConstraints<double>     &constraints,
                            const Function<3>                   *body_force,
                            TrilinosWrappers::SparseMatrix      *matrix,
                            TrilinosWrappers::MPI::Vector       &rhs) const
  {
    if (matrix != nullptr)
      *matrix = 0;
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
    loop(u, nullptr, body_force, matrix != nullptr, [&](const CellData &data) {
      if (data.inverted)
        ++inverted;
      else
        add_block(data.dofs, data.matrix, data.residual);
    });
    for (const DofContribution *contribution : dof_contributions)
      contribution->add_nonlinear(u, matrix != nullptr, add_block);
    if (matrix != nullptr)
      matrix->compress(VectorOperation::add);
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
    loop(u, &w, body_force, false, [&](const CellData &data) {
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
