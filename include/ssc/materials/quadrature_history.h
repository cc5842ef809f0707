#ifndef ssc_materials_quadrature_history_h
#define ssc_materials_quadrature_history_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/types.h>

#include <deal.II/grid/tria.h>

#include <vector>

#include <ssc/materials/material.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The history variables of the laws that keep some (Material::
   * n_history_variables()), per locally owned cell and quadrature point, in
   * two copies: the committed values of the last accepted load or time
   * step, and the trial values the current step writes while Newton's
   * method solves it. Accepting a step commits the trial values; a step the
   * load stepping abandons (cut) restores them, so a retried step starts
   * from the same history. deal.II's CellDataStorage holds the points (as in
   * step-18 and step-44); each cell only touches its own points, so the
   * threaded assembly needs no lock.
   */
  class QuadratureHistory
  {
  public:
    using CellIterator = Triangulation<3>::cell_iterator;

    /// Zero history for the locally owned active cells of @p triangulation
    /// whose material_id m has n_variables_per_material[m] > 0 (ids beyond
    /// the vector have none), @p n_q_points points each; forgets what was
    /// stored before.
    void
    initialize(const Triangulation<3>          &triangulation,
               const std::vector<unsigned int> &n_variables_per_material,
               const unsigned int               n_q_points);

    /// Whether no cell keeps history (elastic laws only).
    bool
    empty() const
    {
      return cells.empty();
    }

    /// The trial values of point @p q of @p cell (which must keep history),
    /// written by the law during the current step.
    ArrayView<double>
    trial(const CellIterator &cell, const unsigned int q);

    /// The values of the last accepted step at point @p q of @p cell.
    ArrayView<const double>
    committed(const CellIterator &cell, const unsigned int q) const;

    /// What the law at each quadrature point of @p cell (which must keep
    /// history) sees in the current step: both copies and the step's
    /// length in time. One lookup per cell, for the assembly.
    std::vector<MaterialPointHistory>
    points(const CellIterator &cell);

    /// The length in time (s) of the step being solved: 0 (the default)
    /// for a load step without time, where the laws answer instantly. Set
    /// it for every step: accept() resets it.
    void
    set_time_step(const double dt)
    {
      time_step = dt;
    }

    double
    get_time_step() const
    {
      return time_step;
    }

    /// The current step is accepted: its trial values become the
    /// committed ones, and the time step goes back to 0, so that what is
    /// assembled before the next step (reactions, output) is the accepted
    /// state, not one relaxed by a further step.
    void
    accept();

    /// The current step is abandoned: the trial values go back to the
    /// committed ones.
    void
    reject();

  private:
    struct PointHistory
    {
      std::vector<double> committed;
      std::vector<double> trial;
    };

    /// Copies one copy of every point's values into the other.
    void
    copy_all(const bool trial_to_committed);

    CellDataStorage<CellIterator, PointHistory> storage;
    std::vector<CellIterator>                   cells;
    double                                      time_step = 0;
  };
} // namespace ssc

#endif
