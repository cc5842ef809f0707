#ifndef ssc_mechanics_small_strain_kernel_h
#define ssc_mechanics_small_strain_kernel_h

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ssc/materials/material.h>
#include <ssc/mechanics/cell_pressure_block.h>
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
    SmallStrainKernel(const ElasticityParameters &parameters,
                      const Quadrature<3>        &quadrature);

    /// K and f of @p cell (@p fe_values reinit'ed on it) for @p material;
    /// with @p block (mixed formulations only) also K's
    /// displacement-pressure structure.
    void
    assemble(const DoFHandler<3>::active_cell_iterator &cell,
             const FEValues<3>                         &fe_values,
             const Material                            &material,
             const GrowthField                         &growth,
             const Function<3>                         *body_force,
             FullMatrix<double>                        &cell_matrix,
             Vector<double>                            &cell_rhs,
             CellPressureBlock                         *block = nullptr) const;

  private:
    const ElasticityParameters &parameters;
    const Quadrature<3>        &quadrature;
  };
} // namespace ssc

#endif
