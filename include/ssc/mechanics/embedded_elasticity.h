#ifndef ssc_mechanics_embedded_elasticity_h
#define ssc_mechanics_embedded_elasticity_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <ssc/embedding/clipped_quadrature.h>
#include <ssc/mechanics/cell_contribution.h>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace ssc
{
  /// Membranes (septa, codimension 1) or cables (ligaments, codimension 2).
  enum class EmbeddedKind
  {
    membrane,
    cable
  };

  /// Linear elastic properties of one embedded cell.
  struct EmbeddedMaterial
  {
    double youngs_modulus; ///< MPa
    double poisson_ratio;  ///< in-plane, membranes only
    /// Thickness (membrane, mm) or cross-section area (cable, mm^2).
    double size;
  };

  /**
   * Small-strain stiffness of membranes or cables embedded in the
   * background mesh without degrees of freedom of their own (DESIGN.md §4):
   * their displacement is the background field at their quadrature points,
   * so their energy enters the background matrix through the background
   * shape-function gradients there.
   *
   * Membrane (plane stress in the tangent plane, projector P = I - n n):
   *   (t/2) int lambda_ps (P:eps)^2 + 2 mu (P eps P):(P eps P) dA,
   *   lambda_ps = 2 lambda mu / (lambda + 2 mu) = E nu / (1 - nu^2).
   * Cable (unit tangent tau):  (E A / 2) int (tau . eps tau)^2 ds.
   *
   * At finite strain (Newton's method) the same laws act on Green-Lagrange
   * strains (St Venant-Kirchhoff): the membrane strain
   * E = (P F^T F P - P) / 2 and the cable strain e = (|F tau|^2 - 1) / 2,
   * optionally tension-only: a compressed cable is slack and carries
   * nothing, a compressed membrane wrinkles (tension-field theory).
   *
   * The quadrature comes split along the locally owned background cells
   * (clipped_quadrature()), so each rank assembles its own cells' part.
   */
  class EmbeddedElasticity : public CellContribution
  {
  public:
    EmbeddedElasticity(
      const EmbeddedKind                                         kind,
      const std::vector<CellQuadrature>                         &quadrature,
      const std::function<EmbeddedMaterial(types::material_id)> &material,
      const FiniteElement<3>                                    &fe,
      const Mapping<3>                                          &mapping,
      const MPI_Comm                                             communicator,
      const bool tension_only = false);

    void
    add_to_cell(const DoFHandler<3>::active_cell_iterator &cell,
                FullMatrix<double>                        &cell_matrix,
                Vector<double> &cell_rhs) const override;

    /// Finite strain: tangent and internal forces of the Green-Lagrange
    /// laws at the cell's displacement @p u.
    void
    add_to_cell_nonlinear(const DoFHandler<3>::active_cell_iterator &cell,
                          const Vector<double>                      &u,
                          const bool          with_matrix,
                          FullMatrix<double> &cell_matrix,
                          Vector<double>     &cell_residual) const override;

    /// Quadrature points on all ranks.
    unsigned int
    n_points() const
    {
      return n_global_points;
    }

    /// Stress of the embedded structure for the background strain
    /// @p strain at a point with direction @p direction and material
    /// @p material, for output: the axial stress of a cable, the von Mises
    /// stress of a membrane (MPa).
    double
    axial_or_membrane_stress(const SymmetricTensor<2, 3> &strain,
                             const Tensor<1, 3>          &direction,
                             const EmbeddedMaterial      &material) const;

  private:
    /// What one located quadrature point needs for the assembly.
    struct LocalPoint
    {
      Point<3>     unit_point;
      Tensor<1, 3> direction;
      /// JxW times the stiffness coefficients: membrane t lambda_ps and
      /// 2 t mu; cable E A (in the first).
      double first, second;
    };

    const EmbeddedKind                   kind;
    const FiniteElement<3>              &fe;
    const Mapping<3>                    &mapping;
    std::vector<std::vector<LocalPoint>> points_per_cell;
    unsigned int                         n_global_points;
    const bool                           tension_only;

    /// Taut, wrinkled or slack (tension-field theory).
    enum class MembraneRegime
    {
      taut,
      wrinkled,
      slack
    };

    /// The membrane's stress and second derivative of its energy at one
    /// point (both already multiplied by t JxW).
    struct MembraneState
    {
      MembraneRegime regime = MembraneRegime::taut;
      Tensor<2, 3>   stress;
      double         lambda = 0, two_mu = 0;
      /// wrinkled: uniaxial modulus, principal strains and directions
      double       youngs = 0, E1 = 0, E2 = 0;
      Tensor<1, 3> n1, n2;

      /// d2W/dE2 [A, B] for tangential strain variations A, B.
      double
      second_derivative(const Tensor<2, 3> &A, const Tensor<2, 3> &B) const;
    };

    /// Stress and tangent of the St Venant-Kirchhoff membrane at Green
    /// strain @p E (tangent projector @p P), relaxed by tension-field
    /// theory when tension_only is set.
    MembraneState
    membrane_state(const Tensor<2, 3> &E,
                   const Tensor<2, 3> &P,
                   const LocalPoint   &point) const;

    /// Two orthonormal vectors of the plane normal to the unit vector
    /// @p normal.
    static std::pair<Tensor<1, 3>, Tensor<1, 3>>
    tangent_basis(const Tensor<1, 3> &normal);

    /// FEValues with the cell's embedded points (reference gradients).
    std::unique_ptr<FEValues<3>>
    reinit_points(const DoFHandler<3>::active_cell_iterator &cell,
                  const std::vector<LocalPoint>             &local) const;
  };
} // namespace ssc

#endif
