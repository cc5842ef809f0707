#ifndef ssc_mechanics_volume_kernel_h
#define ssc_mechanics_volume_kernel_h

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <ssc/materials/layer_materials.h>
#include <ssc/mechanics/elasticity_parameters.h>
#include <ssc/mechanics/finite_strain_kernel.h>
#include <ssc/mechanics/growth_field.h>
#include <ssc/mechanics/small_strain_kernel.h>

namespace ssc
{
  /**
   * The volume's cell routine: the law of the cell's layer decides the
   * kernel (small or finite strain), and both give the residual
   * r = f_int(u) - f_ext and the tangent at the cell's displacement (the
   * small-strain kernel's K u - f, exact for the linear problem). This is
   * the one place the system assembler asks for a cell's contribution.
   */
  class VolumeKernel
  {
  public:
    VolumeKernel(const LayerMaterials       &materials,
                 const ElasticityParameters &parameters,
                 const GrowthField          &growth,
                 QuadratureHistory          &history);

    /// The quadrature of the cell assembly (Gauss with p + 1 points).
    const Quadrature<3> &
    quadrature() const
    {
      return cell_quadrature;
    }

    /// What FEValues must compute for residual_and_tangent().
    static UpdateFlags
    update_flags()
    {
      return update_values | update_gradients | update_quadrature_points |
             update_JxW_values;
    }

    /// The law of @p cell's layer.
    const Material &
    material(const DoFHandler<3>::active_cell_iterator &cell) const
    {
      return materials[cell->material_id()];
    }

    /**
     * Residual into @p copy.residual and tangent into @p copy.matrix (if
     * @p scratch.with_matrix; small-strain cells always) of @p cell at its
     * dof values @p scratch.u, @p scratch.fe_values reinit'ed here and
     * @p scratch.kinematics set to the cell's law's; with @p
     * scratch.with_pressure also the tangent's displacement-pressure
     * structure (mixed formulations). Returns false if the cell is
     * inverted.
     */
    bool
    assemble(const DoFHandler<3>::active_cell_iterator &cell,
             CellScratch                               &scratch,
             CellCopy                                  &copy) const;

  private:
    const LayerMaterials &materials;
    const QGauss<3>       cell_quadrature;
    SmallStrainKernel     small_strain;
    FiniteStrainKernel    finite_strain;
  };
} // namespace ssc

#endif
