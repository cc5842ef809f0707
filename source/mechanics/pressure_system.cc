#include <deal.II/base/mpi.h>

#include <ssc/mechanics/pressure_system.h>

namespace ssc
{
  PressureSystem::PressureSystem(const DoFHandler<3> &dof_handler,
                                 const unsigned int   n_pressure_modes)
    : dof_handler(dof_handler)
    , n_p(n_pressure_modes)
  {
    const auto    &tria         = dof_handler.get_triangulation();
    const MPI_Comm communicator = tria.get_communicator();
    first_of_cell.assign(tria.n_active_cells(), numbers::invalid_unsigned_int);
    unsigned int n_local = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          first_of_cell[cell->active_cell_index()] = n_local;
          n_local += n_p;
        }
    owned = Utilities::MPI::create_ascending_partitioning(
      communicator, n_local)[Utilities::MPI::this_mpi_process(communicator)];
    offset = owned.n_elements() > 0 ? owned.nth_index_in_set(0) : 0;
    pressure_blocks.resize(n_local / std::max(n_p, 1u));
    schur_inverses.resize(pressure_blocks.size());
  }


  void
  PressureSystem::setup(
    const TrilinosWrappers::SparsityPattern &tangent_sparsity,
    const AffineConstraints<double>         &constraints)
  {
    reduced.reinit(tangent_sparsity);
    const MPI_Comm communicator =
      dof_handler.get_triangulation().get_communicator();
    const IndexSet u_owned = dof_handler.locally_owned_dofs();
    TrilinosWrappers::SparsityPattern    sparsity(owned, u_owned, communicator);
    const AffineConstraints<double>      none;
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          none.add_entries_local_to_global(pressure_indices(cell),
                                           constraints,
                                           dofs,
                                           sparsity);
        }
    sparsity.compress();
    coupling.reinit(sparsity);
  }


  void
  PressureSystem::reset()
  {
    reduced  = 0;
    coupling = 0;
  }


  void
  PressureSystem::add_cell(const DoFHandler<3>::active_cell_iterator  &cell,
                           const std::vector<types::global_dof_index> &dofs,
                           const CellPressureBlock                    &block,
                           const AffineConstraints<double> &constraints)
  {
    AssertDimension(block.coupling.m(), n_p);
    AssertDimension(block.coupling.n(), dofs.size());
    const unsigned int first = first_of_cell[cell->active_cell_index()];
    constraints.distribute_local_to_global(block.reduced, dofs, reduced);
    const AffineConstraints<double> none;
    none.distribute_local_to_global(
      block.coupling, pressure_indices(cell), constraints, dofs, coupling);
    pressure_blocks[first / n_p] = block.pressure;
    schur_inverses[first / n_p].reinit(n_p, n_p);
    schur_inverses[first / n_p].invert(block.schur);
  }


  std::vector<types::global_dof_index>
  PressureSystem::pressure_indices(
    const DoFHandler<3>::active_cell_iterator &cell) const
  {
    const unsigned int first = first_of_cell[cell->active_cell_index()];
    Assert(first != numbers::invalid_unsigned_int,
           ExcMessage("A cell that this rank does not own."));
    std::vector<types::global_dof_index> indices(n_p);
    for (unsigned int a = 0; a < n_p; ++a)
      indices[a] = offset + first + a;
    return indices;
  }


  void
  PressureSystem::add_to_reduced(
    const std::vector<types::global_dof_index> &dofs,
    const FullMatrix<double>                   &matrix,
    const AffineConstraints<double>            &constraints)
  {
    constraints.distribute_local_to_global(matrix, dofs, reduced);
  }


  void
  PressureSystem::compress()
  {
    reduced.compress(VectorOperation::add);
    coupling.compress(VectorOperation::add);
  }


  void
  PressureSystem::apply_blocks(const std::vector<FullMatrix<double>> &blocks,
                               TrilinosWrappers::MPI::Vector         &dst,
                               const TrilinosWrappers::MPI::Vector   &src) const
  {
    // the pressure of the locally owned cells is the vector's local part
    const double  *in  = src.begin();
    double        *out = dst.begin();
    Vector<double> x(n_p), y(n_p);
    for (unsigned int c = 0; c < blocks.size(); ++c)
      {
        for (unsigned int a = 0; a < n_p; ++a)
          x(a) = in[c * n_p + a];
        blocks[c].vmult(y, x);
        for (unsigned int a = 0; a < n_p; ++a)
          out[c * n_p + a] = y(a);
      }
  }


  void
  PressureSystem::apply_pressure_block(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    apply_blocks(pressure_blocks, dst, src);
  }


  void
  PressureSystem::apply_schur_inverse(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    apply_blocks(schur_inverses, dst, src);
  }
} // namespace ssc
