#ifndef ssc_mechanics_finite_strain_kernel_h
#define ssc_mechanics_finite_strain_kernel_h

#include <deal.II/base/function.h>

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
   * The residual f_int(u) - f_ext and consistent tangent of a cell of a
   * finite-strain law (Material::isochoric_response() plus the volumetric
   * energy), with growth F = F_e F_g.
   *
   * Displacement formulation: U(J_e) at the quadrature points. Mixed
   * formulations (three-field Hu-Washizu, Simo-Taylor-Pister): the energy
   * int gamma [W_iso + U(theta)] with the dilatation theta the
   * gamma-weighted L2 projection of J / gamma onto the cell's pressure
   * space (P_{p-1} for mixed, P0 for the mean dilatation), the pressure
   * p the projection of U'(theta), both condensed out: with M_ab = int
   * gamma q_a q_b, B_ai = int q_a J div(phi_i) and H_ab = int gamma U''(theta)
   * q_a q_b, the volumetric tangent is B^T M^{-1} H M^{-1} B plus the
   * geometric part of p. A share beta (Volumetric stabilisation) of U is
   * taken at the quadrature points instead.
   */
  class FiniteStrainKernel
  {
  public:
    explicit FiniteStrainKernel(const ElasticityParameters &parameters);

    /// Residual @p cell_residual and (if @p with_matrix) tangent @p
    /// cell_matrix of @p cell (@p fe_values reinit'ed on it) at its dof
    /// values @p u for @p material. Returns false if the cell is inverted
    /// (det F or the projected dilatation <= 0 at a quadrature point).
    /// With @p block (mixed formulations, with the matrix) also the
    /// tangent's displacement-pressure structure.
    bool
    assemble(const DoFHandler<3>::active_cell_iterator &cell,
             const FEValues<3>                         &fe_values,
             const Material                            &material,
             const GrowthField                         &growth,
             const Function<3>                         *body_force,
             const Vector<double>                      &u,
             const bool                                 with_matrix,
             FullMatrix<double>                        &cell_matrix,
             Vector<double>                            &cell_residual,
             CellPressureBlock                         *block = nullptr) const;

  private:
    const ElasticityParameters &parameters;
  };
} // namespace ssc

#endif
