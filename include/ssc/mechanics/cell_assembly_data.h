#ifndef ssc_mechanics_cell_assembly_data_h
#define ssc_mechanics_cell_assembly_data_h

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

#include <ssc/materials/material.h>
#include <ssc/mechanics/cell_pressure_block.h>

namespace ssc
{
  using namespace dealii;

  /**
   * What the cell loop hands every cell kernel and cell contribution (the
   * scratch data of MeshWorker::mesh_loop, one per thread): the cell's
   * FEValues, its displacement values, and what this assembly asks for.
   * Kernels then read (cell, scratch) and write their copy data,
   * CellCopy, as step-44's and fsi-suite's assemblers do.
   */
  struct CellScratch
  {
    CellScratch(const Mapping<3>       &mapping,
                const FiniteElement<3> &fe,
                const Quadrature<3>    &quadrature,
                const UpdateFlags       flags);

    /// A fresh copy for another thread (FEValues cannot be copied).
    CellScratch(const CellScratch &other);

    /// Reinitialised on the cell by the volume kernel.
    FEValues<3> fe_values;
    /// The cell's displacement dof values.
    Vector<double> u;
    /// The cell's weight dof values (reactions: one on a condition's dofs).
    Vector<double> w;
    /// Body force per unit volume (N/mm^3), or none.
    const Function<3> *body_force = nullptr;
    /// Whether the tangent is wanted (small-strain cells give it always).
    bool with_matrix = true;
    /// Whether the tangent's displacement-pressure structure is wanted
    /// (mixed formulations, block preconditioner).
    bool with_pressure = false;
    /// The kinematics of the cell's law: a contribution inside a
    /// small-strain cell is linear too (set by the volume kernel).
    Kinematics kinematics = Kinematics::small_strain;
  };


  /// What one cell gives to the global system (the copy data of the loop).
  struct CellCopy
  {
    /// Sizes matrix, residual and dofs for @p n dofs, zeroes them and the
    /// flags, and remembers @p cell.
    void
    reinit(const DoFHandler<3>::active_cell_iterator &cell,
           const unsigned int                         n);

    DoFHandler<3>::active_cell_iterator cell;
    /// The tangent (or, from the small-strain kernel before the volume
    /// kernel turns it into a residual, K).
    FullMatrix<double> matrix;
    /// The residual f_int(u) - f_ext (or the small-strain load f).
    Vector<double>                       residual;
    std::vector<types::global_dof_index> dofs;
    /// The displacement-pressure structure, if CellScratch::with_pressure.
    CellPressureBlock pressure;
    /// The cell is inverted: its contributions are left out.
    bool inverted = false;
    /// The cell's weight vanishes: nothing was computed.
    bool skipped = false;
  };
} // namespace ssc

#endif
