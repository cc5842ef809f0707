#include <ssc/mechanics/volume_kernel.h>

namespace ssc
{
  VolumeKernel::VolumeKernel(const LayerMaterials       &materials,
                             const ElasticityParameters &parameters,
                             const GrowthField          &growth,
                             QuadratureHistory          &history)
    : materials(materials)
    , cell_quadrature(parameters.degree + 1)
    , small_strain(parameters, cell_quadrature, materials, growth)
    , finite_strain(parameters, materials, growth, history)
  {
    AssertThrow(growth.n_points() == cell_quadrature.size(),
                ExcMessage("The growth field must be sampled at the "
                           "assembly's quadrature points."));
  }


  bool
  VolumeKernel::assemble(const DoFHandler<3>::active_cell_iterator &cell,
                         CellScratch                               &scratch,
                         CellCopy                                  &copy) const
  {
    scratch.fe_values.reinit(cell);
    scratch.kinematics = material(cell).kinematics();
    if (scratch.kinematics == Kinematics::finite_strain)
      return finite_strain.assemble(cell, scratch, copy);
    // r = K u - f
    small_strain.assemble(cell, scratch, copy);
    copy.residual *= -1.;
    copy.matrix.vmult_add(copy.residual, scratch.u);
    return true;
  }
} // namespace ssc
