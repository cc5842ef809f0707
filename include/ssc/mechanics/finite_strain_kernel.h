#ifndef ssc_mechanics_finite_strain_kernel_h
#define ssc_mechanics_finite_strain_kernel_h

#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

#include <ssc/materials/layer_materials.h>
#include <ssc/materials/quadrature_history.h>
#include <ssc/mechanics/cell_assembly_data.h>
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
    /// The kernel of the layers' laws @p materials, with the growth of
    /// @p growth; the laws with history read and write theirs in
    /// @p history (each cell its own points: safe in the threaded loop).
    FiniteStrainKernel(const ElasticityParameters &parameters,
                       const LayerMaterials       &materials,
                       const GrowthField          &growth,
                       QuadratureHistory          &history);

    /// Residual into @p copy.residual and (if @p scratch.with_matrix)
    /// tangent into @p copy.matrix of @p cell (@p scratch.fe_values
    /// reinit'ed on it) at its dof values @p scratch.u. Returns false if
    /// the cell is inverted (det F or the projected dilatation <= 0 at a
    /// quadrature point). With @p scratch.with_pressure (mixed
    /// formulations, with the matrix) also the tangent's
    /// displacement-pressure structure into @p copy.pressure.
    bool
    assemble(const DoFHandler<3>::active_cell_iterator &cell,
             const CellScratch                         &scratch,
             CellCopy                                  &copy) const;

  private:
    struct ProjectedDilatation;

    /// F and the growth ratio gamma = 1 + g at the quadrature points;
    /// false if det F <= 0 somewhere.
    bool
    deformation_gradients(const DoFHandler<3>::active_cell_iterator &cell,
                          const CellScratch                         &scratch,
                          std::vector<Tensor<2, 3>>                 &F,
                          std::vector<double> &gamma) const;

    /// The projected dilatation theta and pressure of the mixed
    /// formulations; false if theta <= 0 somewhere.
    bool
    project_dilatation(const DoFHandler<3>::active_cell_iterator &cell,
                       const CellScratch                         &scratch,
                       const std::vector<Tensor<2, 3>>           &F,
                       const std::vector<double>                 &gamma,
                       ProjectedDilatation &projection) const;

    /// The quadrature loop: residual and tangent (isochoric, geometric and
    /// the volumetric share at the points) and, with the tangent, B = int
    /// q_a J div(phi_i).
    void
    integrate(const DoFHandler<3>::active_cell_iterator &cell,
              const CellScratch                         &scratch,
              const std::vector<Tensor<2, 3>>           &F,
              const std::vector<double>                 &gamma,
              const ProjectedDilatation                 &projection,
              FullMatrix<double>                        &B,
              CellCopy                                  &copy) const;

    /// The condensed volumetric part (1 - beta) B^T M^{-1} H M^{-1} B and
    /// the pressure block, if asked for.
    void
    add_projected_volumetric(const DoFHandler<3>::active_cell_iterator &cell,
                             const CellScratch                         &scratch,
                             const ProjectedDilatation &projection,
                             const FullMatrix<double>  &B,
                             CellCopy                  &copy) const;

    const ElasticityParameters &parameters;
    const LayerMaterials       &materials;
    const GrowthField          &growth;
    QuadratureHistory          &history;
  };
} // namespace ssc

#endif
