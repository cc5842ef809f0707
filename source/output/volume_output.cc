#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/data_out.h>

#include <limits>

#include <ssc/output/volume_output.h>

namespace ssc
{
  std::vector<SymmetricTensor<2, 3>>
  cell_cauchy_stresses(const DisplacementField &field,
                       const LayerMaterials    &materials,
                       const GrowthField       &growth,
                       const QuadratureHistory &history)
  {
    // the assembly's quadrature, at whose points the growth is known
    const QGauss<3> quadrature(field.fe().degree + 1);
    AssertThrow(growth.n_points() == quadrature.size(),
                ExcMessage("The growth field is sampled at other points."));
    FEValues<3>                        fe_values(field.mapping(),
                          field.fe(),
                          quadrature,
                          update_gradients | update_quadrature_points |
                            update_JxW_values);
    const FEValuesExtractors::Vector   displacement(0);
    std::vector<Tensor<2, 3>>          gradients(quadrature.size());
    std::vector<SymmetricTensor<2, 3>> stresses(
      field.triangulation().n_active_cells());
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(field.solution(),
                                                         gradients);
          const Material &law = materials[cell->material_id()];
          const bool finite   = law.kinematics() == Kinematics::finite_strain;
          // the mean of sigma over the deformed cell: weights J dV (dV at
          // small strain)
          SymmetricTensor<2, 3> sigma;
          double                volume = 0;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Tensor<2, 3> F = unit_symmetric_tensor<3>() + gradients[q];
              const double       J = finite ? determinant(F) : 1.;
              if (!(J > 0))
                {
                  volume = std::numeric_limits<double>::quiet_NaN();
                  break;
                }
              const Point<3> &X     = fe_values.quadrature_point(q);
              const double    gamma = 1. + growth.at(cell, q);
              sigma += (law.n_history_variables() > 0 ?
                          law.accepted_cauchy_stress(
                            X, F, gamma, history.committed(cell, q)) :
                          law.cauchy_stress(X, F, gamma)) *
                       J * fe_values.JxW(q);
              volume += J * fe_values.JxW(q);
            }
          stresses[cell->active_cell_index()] = sigma / volume;
        }
    return stresses;
  }


  std::string
  write_volume_vtu(const DisplacementField &field,
                   const LayerMaterials    &materials,
                   const GrowthField       &growth,
                   const QuadratureHistory &history,
                   const RunOutput         &output,
                   const unsigned int       step)
  {
    const auto                              &tria    = field.triangulation();
    const unsigned int                       n_cells = tria.n_active_cells();
    const std::vector<SymmetricTensor<2, 3>> sigma =
      cell_cauchy_stresses(field, materials, growth, history);
    std::vector<Vector<float>> stress(6, Vector<float>(n_cells));
    Vector<float> mises(n_cells), layer(n_cells), subdomain(n_cells);
    static constexpr unsigned int index[6][2] = {
      {0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int k = cell->active_cell_index();
          for (unsigned int c = 0; c < 6; ++c)
            stress[c][k] = sigma[k][index[c][0]][index[c][1]];
          mises[k]     = von_mises(sigma[k]);
          layer[k]     = cell->material_id();
          subdomain[k] = tria.locally_owned_subdomain();
        }

    DataOut<3> data_out;
    data_out.attach_dof_handler(field.dof_handler());
    const std::vector<std::string> names(3, "displacement");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(3,
                     DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(field.solution(),
                             names,
                             DataOut<3>::type_dof_data,
                             interpretation);
    const char *stress_names[6] = {"stress_xx",
                                   "stress_yy",
                                   "stress_zz",
                                   "stress_xy",
                                   "stress_yz",
                                   "stress_xz"};
    for (unsigned int c = 0; c < 6; ++c)
      data_out.add_data_vector(stress[c], stress_names[c]);
    data_out.add_data_vector(mises, "von_mises");
    data_out.add_data_vector(layer, "layer");
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(field.mapping(), field.fe().degree);
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    return output.write_vtu(data_out, "volume", step);
  }
} // namespace ssc
