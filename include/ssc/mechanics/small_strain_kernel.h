#ifndef ssc_mechanics_small_strain_kernel_h
#define ssc_mechanics_small_strain_kernel_h

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ssc/materials/layer_materials.h>
#include <ssc/mechanics/cell_assembly_data.h>
#include <ssc/mechanics/elasticity_parameters.h>
#include <ssc/mechanics/growth_field.h>

namespace ssc
{
  /**
   * The cell matrix and load of small-strain elasticity: the deviatoric
   * part from the law's small-strain tangent, the volumetric part
   * kappa (tr eps)^2 / 2 taken either at the quadrature points
   * (displacement formulation) or on the dilatation projected onto the
   * cell's pressure space (mixed, mean dilatation: B-bar), and for the
   * enhanced formulation the nine Wilson-Taylor incompatible modes,
   * condensed statically. Loads: the body force and the growth eigenstrain
   * (g/3) I, which loads the (projected) dilatation.
   */
  class SmallStrainKernel
  {
  public:
    /// The kernel of the layers' laws @p materials, with the growth
    /// eigenstrain of @p growth, on the cell quadrature @p quadrature.
    SmallStrainKernel(const ElasticityParameters &parameters,
                      const Quadrature<3>        &quadrature,
                      const LayerMaterials       &materials,
                      const GrowthField          &growth);

    /// K into @p copy.matrix and f into @p copy.residual for @p cell
    /// (@p scratch.fe_values reinit'ed on it); with @p
    /// scratch.with_pressure (mixed formulations only) also K's
    /// displacement-pressure structure into @p copy.pressure.
    void
    assemble(const DoFHandler<3>::active_cell_iterator &cell,
             const CellScratch                         &scratch,
             CellCopy                                  &copy) const;

  private:
    struct ModeIntegrals;

    /// The quadrature loop: the integrals over the strain modes into
    /// @p integrals and the body force's load into @p cell_rhs.
    void
    integrate_modes(const DoFHandler<3>::active_cell_iterator &cell,
                    const CellScratch                         &scratch,
                    ModeIntegrals                             &integrals,
                    Vector<double>                            &cell_rhs) const;

    const ElasticityParameters &parameters;
    const Quadrature<3>        &quadrature;
    const LayerMaterials       &materials;
    const GrowthField          &growth;
  };
} // namespace ssc

#endif
