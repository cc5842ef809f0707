#include <ssc/mechanics/volume_kernel.h>

namespace ssc
{
  VolumeKernel::VolumeKernel(const LayerMaterials       &materials,
                             const ElasticityParameters &parameters,
                             const GrowthField          &growth)
    : materials(materials)
    , growth(growth)
    , cell_quadrature(parameters.degree + 1)
    , small_strain(parameters, cell_quadrature)
    , finite_strain(parameters)
  {
    AssertThrow(growth.n_points() == cell_quadrature.size(),
                ExcMessage("The growth field must be sampled at the "
                           "assembly's quadrature points."));
  }


  bool
  VolumeKernel::residual_and_tangent(
    const DoFHandler<3>::active_cell_iterator &cell,
    FEValues<3>                               &fe_values,
    const Vector<double>                      &u,
    const Function<3>                         *body_force,
    const bool                                 with_matrix,
    FullMatrix<double>                        &cell_matrix,
    Vector<double>                            &cell_residual,
    CellPressureBlock                         *block) const
  {
    fe_values.reinit(cell);
    const Material &law = material(cell);
    if (law.kinematics() == Kinematics::finite_strain)
      return finite_strain.assemble(cell,
                                    fe_values,
                                    law,
                                    growth,
                                    body_force,
                                    u,
                                    with_matrix,
                                    cell_matrix,
                                    cell_residual,
                                    block);
    // r = K u - f
    small_strain.assemble(cell,
                          fe_values,
                          law,
                          growth,
                          body_force,
                          cell_matrix,
                          cell_residual,
                          block);
    cell_residual *= -1.;
    cell_matrix.vmult_add(cell_residual, u);
    return true;
  }
} // namespace ssc
