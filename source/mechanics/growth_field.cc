#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_values.h>

#include <ssc/mechanics/growth_field.h>

namespace ssc
{
  void
  GrowthField::sample(
    const DisplacementField                                           &field,
    const std::function<double(const Point<3> &, const unsigned int)> &growth)
  {
    values.assign(field.dof_handler().get_triangulation().n_active_cells() *
                    n_points_per_cell,
                  0.);
    FEValues<3> fe_values(field.mapping(),
                          field.fe(),
                          quadrature,
                          update_quadrature_points);
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < n_points_per_cell; ++q)
            {
              const double g =
                growth(fe_values.quadrature_point(q), cell->material_id());
              AssertThrow(g > -1.,
                          ExcMessage("A growth ratio g <= -1 would remove "
                                     "all the material."));
              values[cell->active_cell_index() * n_points_per_cell + q] = g;
            }
        }
    growth_scale = 1.;
  }


  double
  GrowthField::volume(const DisplacementField &field) const
  {
    double volume = 0;
    if (!values.empty())
      {
        FEValues<3> fe_values(field.mapping(),
                              field.fe(),
                              quadrature,
                              update_JxW_values);
        for (const auto &cell : field.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              for (unsigned int q = 0; q < n_points_per_cell; ++q)
                volume +=
                  values[cell->active_cell_index() * n_points_per_cell + q] *
                  fe_values.JxW(q);
            }
      }
    return Utilities::MPI::sum(
      volume, field.dof_handler().get_triangulation().get_communicator());
  }
} // namespace ssc
