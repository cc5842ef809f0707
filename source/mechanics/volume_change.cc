#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <ssc/mechanics/volume_change.h>

namespace ssc
{
  double
  volume_change(const DisplacementField &field, const LayerMaterials &materials)
  {
    const QGauss<3>                  quadrature(field.fe().degree + 1);
    FEValues<3>                      fe_values(field.mapping(),
                          field.fe(),
                          quadrature,
                          update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector u(0);
    std::vector<Tensor<2, 3>>        gradients(quadrature.size());
    double                           change = 0;
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_gradients(field.solution(), gradients);
          const bool small_strain =
            materials[cell->material_id()].kinematics() ==
            Kinematics::small_strain;
          for (unsigned int q = 0; q < gradients.size(); ++q)
            change +=
              (small_strain ?
                 trace(gradients[q]) :
                 determinant(unit_symmetric_tensor<3>() + gradients[q]) - 1.) *
              fe_values.JxW(q);
        }
    return Utilities::MPI::sum(
      change, field.dof_handler().get_triangulation().get_communicator());
  }
} // namespace ssc
