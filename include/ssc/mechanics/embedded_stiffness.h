#ifndef ssc_mechanics_embedded_stiffness_h
#define ssc_mechanics_embedded_stiffness_h

#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>

#include <functional>
#include <optional>
#include <vector>

#include <ssc/embedding/clipped_quadrature.h>
#include <ssc/materials/cable_law.h>
#include <ssc/materials/membrane_law.h>
#include <ssc/mechanics/cell_contribution.h>
#include <ssc/mechanics/growth_field.h>

namespace ssc
{
  /**
   * The stiffness of membranes (septa, codimension 1) or cables (ligaments,
   * codimension 2) embedded in the background mesh without degrees of
   * freedom of their own (docs/architecture.md §9): their displacement is the
   * background field at their quadrature points, so their energy (the
   * MembraneLaw or CableLaw) enters the background cells through the
   * background shape-function gradients there. Small strain inside
   * small-strain cells, Green-Lagrange strains (St Venant-Kirchhoff) inside
   * finite-strain ones.
   *
   * The quadrature comes split along the locally owned background cells
   * (clipped_quadrature()), so each rank assembles its own cells' part.
   */
  class EmbeddedStiffness : public CellContribution
  {
  public:
    /// Membranes of law @p law on the pieces @p quadrature.
    EmbeddedStiffness(const std::vector<CellQuadrature> &quadrature,
                      const MembraneLaw                 &law,
                      const FiniteElement<3>            &fe,
                      const Mapping<3>                  &mapping,
                      const MPI_Comm                     communicator);

    /// Cables of law @p law on the pieces @p quadrature.
    EmbeddedStiffness(const std::vector<CellQuadrature> &quadrature,
                      const CableLaw                    &law,
                      const FiniteElement<3>            &fe,
                      const Mapping<3>                  &mapping,
                      const MPI_Comm                     communicator);

    void
    add_to_cell(const DoFHandler<3>::active_cell_iterator &cell,
                const CellScratch                         &scratch,
                CellCopy                                  &copy) const override;

    /**
     * Lets membranes grow with the material around them (septa that
     * remodel with the fat): the stress-free state of the membrane at a
     * point is its reference stretched in its plane by lambda_g = (1 +
     * @p follow s w)^{1/3}, s the current scale of @p growth and w =
     * @p weight(material id of the point: its septum); the energy per reference
     * area is then lambda_g^2 W(E_e) with E_e = (P C P / lambda_g^2 - P) / 2
     * (finite strain), the eigenstrain (lambda_g^3 - 1) / 3 P at small
     * strain. @p follow = 1 grows the membranes as the isotropic growth s w
     * grows a line of the volume; 0 keeps them as they are. @p growth must
     * outlive this.
     */
    void
    grow_with(const GrowthField                                     &growth,
              const std::function<double(const types::material_id)> &weight,
              const double                                           follow);

    /// The in-plane growth stretch squared, lambda_g^2, of the point with
    /// growth weight @p weight (1 without growth).
    double
    growth_stretch_square(const double weight) const;

    /// Quadrature points on all ranks.
    unsigned int
    n_points() const
    {
      return n_global_points;
    }

  private:
    /// The volume ratio of a membrane's growth less one, follow s w, at a
    /// point with growth weight @p weight (0 without growth).
    double
    growth_ratio(const double weight) const;

    /// What one located quadrature point needs for the assembly. The
    /// reference gradients of the cell's shape functions at the point are
    /// kept: the background mesh does not move (total Lagrangian), so they
    /// need not be evaluated again at every assembly (an FEValues built per
    /// cell, as until 2026-12-07).
    struct LocalPoint
    {
      Tensor<1, 3>       direction;
      double             JxW;
      types::material_id material;          ///< of the embedded cell
      double             growth_weight = 0; ///< w of grow_with()
      /// grad N_alpha of each scalar base function alpha (the dofs of all
      /// three components share them)
      std::vector<Tensor<1, 3>> base_gradients;
    };

    void
    setup_points(const std::vector<CellQuadrature> &quadrature,
                 const Mapping<3>                  &mapping,
                 const MPI_Comm                     communicator);

    /// Small strain: K u - f with the linear law.
    void
    add_linear(const std::vector<LocalPoint> &local,
               const Vector<double>          &u,
               FullMatrix<double>            &cell_matrix,
               Vector<double>                &cell_residual) const;

    /// Finite strain: the cable's Green strain.
    void
    add_cable(const std::vector<LocalPoint> &local,
              const Vector<double>          &u,
              const bool                     with_matrix,
              FullMatrix<double>            &cell_matrix,
              Vector<double>                &cell_residual) const;

    /// Finite strain: the membrane's Green strain.
    void
    add_membrane(const std::vector<LocalPoint> &local,
                 const Vector<double>          &u,
                 const bool                     with_matrix,
                 FullMatrix<double>            &cell_matrix,
                 Vector<double>                &cell_residual) const;

    /// F = I + grad u at @p point, with the reference gradients of the
    /// shape functions (of their own component) into @p gradients.
    Tensor<2, 3>
    deformation_gradient(const LocalPoint          &point,
                         const Vector<double>      &u,
                         std::vector<Tensor<1, 3>> &gradients) const;

    std::optional<MembraneLaw> membrane;
    std::optional<CableLaw>    cable;
    const FiniteElement<3>    &fe;
    /// The displacement component and the scalar base function of each of
    /// a cell's dofs.
    std::vector<unsigned int>            component, base;
    std::vector<std::vector<LocalPoint>> points_per_cell;
    /// The growth the membranes follow (null: they do not grow).
    const GrowthField *growth          = nullptr;
    double             growth_follow   = 0;
    unsigned int       n_global_points = 0;
  };
} // namespace ssc

#endif
