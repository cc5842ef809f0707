#include <ssc/mechanics/cell_assembly_data.h>

namespace ssc
{
  CellScratch::CellScratch(const Mapping<3>       &mapping,
                           const FiniteElement<3> &fe,
                           const Quadrature<3>    &quadrature,
                           const UpdateFlags       flags)
    : fe_values(mapping, fe, quadrature, flags)
    , u(fe.n_dofs_per_cell())
    , w(fe.n_dofs_per_cell())
  {}


  CellScratch::CellScratch(const CellScratch &other)
    : fe_values(other.fe_values.get_mapping(),
                other.fe_values.get_fe(),
                other.fe_values.get_quadrature(),
                other.fe_values.get_update_flags())
    , u(other.u.size())
    , w(other.w.size())
    , body_force(other.body_force)
    , with_matrix(other.with_matrix)
    , with_pressure(other.with_pressure)
    , kinematics(other.kinematics)
  {}


  void
  CellCopy::reinit(const DoFHandler<3>::active_cell_iterator &new_cell,
                   const unsigned int                         n)
  {
    matrix.reinit(n, n);
    residual.reinit(n);
    dofs.resize(n);
    inverted = false;
    skipped  = false;
    cell     = new_cell;
  }
} // namespace ssc
