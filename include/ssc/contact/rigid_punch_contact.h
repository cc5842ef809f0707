#ifndef ssc_contact_rigid_punch_contact_h
#define ssc_contact_rigid_punch_contact_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <functional>
#include <vector>

#include <ssc/mechanics/dof_contribution.h>

namespace ssc
{
  /// A flat cylindrical punch of radius R whose bottom edge is rounded with
  /// radius rho (a torus); its face is the plane z = face height, its axis
  /// the vertical through (x_c, y_c).
  struct PunchGeometry
  {
    Point<2> centre;
    double   radius      = 2.5;
    double   edge_radius = 0.5;
  };

  /// Signed distance of a point from the punch (negative inside) and its
  /// first and second derivatives with respect to q = (x, y, z, face height).
  struct PunchGap
  {
    double       value = 0;
    Tensor<1, 4> gradient;
    Tensor<2, 4> hessian;
  };

  /**
   * Signed distance of @p x from the punch of @p geometry whose face is at
   * height @p face: the face below the start of the rounding, the torus of
   * the edge below its centre line, the cylinder wall above it. It is C^1
   * across those three parts.
   */
  PunchGap
  punch_gap(const PunchGeometry &geometry,
            const Point<3>      &x,
            const double         face);

  /**
   * Frictionless penalty contact of the skin surface around a rigid flat
   * punch with the punch's rounded edge and face: a finite-strain
   * indentation draws the skin beside the punch around its edge and under
   * it; without this contact the skin passes through the punch there.
   *
   * The energy is the integral over the top faces near the punch of
   * eps/2 <-g>^2, g = punch_gap() at the current position of each
   * quadrature point (4 x 4 Gauss points per face, so that a face
   * crossing the edge is caught between its vertices), eps = (penalty
   * factor) E / h with E the modulus of the top layer and h the face size:
   * the penetration is about 1/(penalty factor) of a cell at the contact
   * pressure E. The face height is the value of one dof (the master of the
   * punch's tie), so each face's block couples its dofs to it and force
   * control stays consistent: the force on the punch includes the contact.
   */
  class RigidPunchContact : public DofContribution
  {
  public:
    /**
     * Takes the locally owned top faces (boundary @p top) with a vertex
     * that the punch does not hold (@p held false: beyond the tied region,
     * under the rounding or beyond the rim) and whose centre lies within
     * @p reach of the axis. @p face_dof gives the dof whose value is the
     * face height (called once the ties exist).
     */
    RigidPunchContact(const PunchGeometry     &geometry,
                      const double             penalty_factor,
                      const double             youngs_modulus,
                      const double             reach,
                      const DoFHandler<3>     &dof_handler,
                      const Mapping<3>        &mapping,
                      const types::boundary_id top,
                      const std::function<bool(const Point<3> &)> &held,
                      std::function<types::global_dof_index()>     face_dof);

    std::vector<std::vector<types::global_dof_index>>
    couplings() const override;

    void
    add_nonlinear(const TrilinosWrappers::MPI::Vector &u,
                  const bool                           with_tangent,
                  const BlockSink                     &add) const override;

    /// Area in contact (mm^2, reference) and largest penetration (mm) at
    /// @p u (collective).
    std::pair<double, double>
    contact_state(const TrilinosWrappers::MPI::Vector &u) const;

    /// Faces that can come into contact, on all ranks (collective).
    unsigned int
    n_faces() const;

  private:
    /// A top face near the punch: its displacement dofs, its penalty eps
    /// and, at each quadrature point, the reference position, the values
    /// of those dofs' shape functions and the area weight JxW.
    struct Face
    {
      std::vector<types::global_dof_index> dofs;
      std::vector<unsigned int>            components;
      double                               penalty = 0;
      std::vector<Point<3>>                points;
      std::vector<std::vector<double>>     shape_values; // [q][k]
      std::vector<double>                  areas;
    };

    /// Calls @p f(face, q, gap) for every quadrature point that
    /// penetrates the punch at @p u.
    void
    for_each_penetration(
      const TrilinosWrappers::MPI::Vector &u,
      const std::function<void(const Face &, unsigned int, const PunchGap &)>
        &f) const;

    const PunchGeometry                      geometry;
    std::vector<Face>                        faces;
    std::function<types::global_dof_index()> face_dof;
    MPI_Comm                                 mpi_communicator;
  };
} // namespace ssc

#endif
