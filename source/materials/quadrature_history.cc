#include <utility>

#include <ssc/materials/quadrature_history.h>

namespace ssc
{
  void
  QuadratureHistory::initialize(
    const Triangulation<3>          &triangulation,
    const std::vector<unsigned int> &n_variables_per_material,
    const unsigned int               n_q_points)
  {
    storage.clear();
    cells.clear();
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        if (!cell->is_locally_owned() ||
            cell->material_id() >= n_variables_per_material.size())
          continue;
        const unsigned int n_variables =
          n_variables_per_material[cell->material_id()];
        if (n_variables == 0)
          continue;
        storage.initialize(cell, n_q_points);
        for (const auto &point : storage.get_data(cell))
          {
            point->committed.assign(n_variables, 0.);
            point->trial.assign(n_variables, 0.);
          }
        cells.push_back(cell);
      }
  }


  ArrayView<double>
  QuadratureHistory::trial(const CellIterator &cell, const unsigned int q)
  {
    const auto points = storage.try_get_data(cell);
    Assert(points && q < points->size(),
           ExcMessage("This cell keeps no history at this point."));
    return make_array_view((*points)[q]->trial);
  }


  ArrayView<const double>
  QuadratureHistory::committed(const CellIterator &cell,
                               const unsigned int  q) const
  {
    const auto points = storage.try_get_data(cell);
    Assert(points && q < points->size(),
           ExcMessage("This cell keeps no history at this point."));
    return make_array_view((*points)[q]->committed);
  }


  std::vector<MaterialPointHistory>
  QuadratureHistory::points(const CellIterator &cell)
  {
    const auto stored = storage.try_get_data(cell);
    Assert(stored, ExcMessage("This cell keeps no history."));
    std::vector<MaterialPointHistory> views;
    views.reserve(stored->size());
    for (const auto &point : *stored)
      views.push_back({make_array_view(std::as_const(point->committed)),
                       make_array_view(point->trial),
                       time_step});
    return views;
  }


  void
  QuadratureHistory::accept()
  {
    copy_all(true);
    // until the next step sets its length, an assembly (reactions, output)
    // evaluates the accepted state itself, not a further relaxation
    time_step = 0;
  }


  void
  QuadratureHistory::reject()
  {
    copy_all(false);
  }


  void
  QuadratureHistory::copy_all(const bool trial_to_committed)
  {
    for (const auto &cell : cells)
      for (const auto &point : storage.get_data(cell))
        if (trial_to_committed)
          point->committed = point->trial;
        else
          point->trial = point->committed;
  }
} // namespace ssc
