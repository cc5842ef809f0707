#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_values.h>

#include <ssc/mechanics/growth_field.h>

namespace ssc
{
  void
  GrowthField::for_each_point(
    const DisplacementField &field,
    const UpdateFlags        flags,
    const std::function<void(unsigned int, const FEValues<3> &, unsigned int)>
      &f) const
  {
    FEValues<3> fe_values(field.mapping(), field.fe(), quadrature, flags);
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < n_points_per_cell; ++q)
            f(cell->active_cell_index() * n_points_per_cell + q, fe_values, q);
        }
  }


  void
  GrowthField::sample(
    const DisplacementField                                           &field,
    const std::function<double(const Point<3> &, const unsigned int)> &growth)
  {
    values.assign(field.triangulation().n_active_cells() * n_points_per_cell,
                  0.);
    for_each_point(field,
                   update_quadrature_points,
                   [&](const unsigned int index,
                       const FEValues<3> &fe_values,
                       const unsigned int q) {
                     const double g =
                       growth(fe_values.quadrature_point(q),
                              fe_values.get_cell()->material_id());
                     AssertThrow(g > -1.,
                                 ExcMessage("A growth ratio g <= -1 would "
                                            "remove all the material."));
                     values[index] = g;
                   });
    growth_scale = 1.;
  }


  double
  GrowthField::volume(const DisplacementField &field) const
  {
    double volume = 0;
    if (!values.empty())
      for_each_point(field,
                     update_JxW_values,
                     [&](const unsigned int index,
                         const FEValues<3> &fe_values,
                         const unsigned int q) {
                       volume += values[index] * fe_values.JxW(q);
                     });
    return Utilities::MPI::sum(volume,
                               field.triangulation().get_communicator());
  }
} // namespace ssc
