#ifndef ssc_scenes_punch_parameters_h
#define ssc_scenes_punch_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <vector>

#include <ssc/base/enum_table.h>

namespace ssc
{
  using namespace dealii;

  /// Bonded: the punch holds all displacement components of the skin under
  /// it; frictionless: only the vertical one (Sneddon's problem); friction:
  /// the vertical one, and Coulomb friction acts in the tangential ones.
  enum class PunchContact
  {
    bonded,
    frictionless,
    friction
  };

  constexpr std::array<std::pair<PunchContact, const char *>, 3>
  enum_table(PunchContact)
  {
    return {{{PunchContact::bonded, "bonded"},
             {PunchContact::frictionless, "frictionless"},
             {PunchContact::friction, "friction"}}};
  }

  /// Which skin nodes the punch holds (the tie): all under its radius, or
  /// only those under the flat part of its face inside the edge rounding.
  enum class PunchTiedRegion
  {
    whole_face,
    flat_face
  };

  constexpr std::array<std::pair<PunchTiedRegion, const char *>, 2>
  enum_table(PunchTiedRegion)
  {
    return {{{PunchTiedRegion::whole_face, "whole face"},
             {PunchTiedRegion::flat_face, "flat face"}}};
  }

  /// Whether the punch's depth or its force is prescribed.
  enum class PunchControl
  {
    displacement,
    force
  };

  constexpr std::array<std::pair<PunchControl, const char *>, 2>
  enum_table(PunchControl)
  {
    return {{{PunchControl::displacement, "displacement"},
             {PunchControl::force, "force"}}};
  }

  /// How the run estimates the discretisation error of the depth at each
  /// force: not at all, by one Newton step of the next richer element on
  /// the same mesh (EnrichedDepthEstimate), or by Richardson from a second
  /// path on the mesh with one global refinement fewer
  /// (CoarserMeshDepthEstimate).
  enum class DepthErrorEstimate
  {
    none,
    enriched_degree,
    coarser_mesh
  };

  constexpr std::array<std::pair<DepthErrorEstimate, const char *>, 3>
  enum_table(DepthErrorEstimate)
  {
    return {{{DepthErrorEstimate::none, "none"},
             {DepthErrorEstimate::enriched_degree, "enriched degree"},
             {DepthErrorEstimate::coarser_mesh, "coarser mesh"}}};
  }

  /// The punch's flat face: a disk (the forearm indenters) or a rectangle
  /// (the face of an ultrasound probe).
  enum class PunchShape
  {
    circle,
    rectangle
  };

  constexpr std::array<std::pair<PunchShape, const char *>, 2>
  enum_table(PunchShape)
  {
    return {
      {{PunchShape::circle, "circle"}, {PunchShape::rectangle, "rectangle"}}};
  }

  /// A rigid flat punch centred at the patch centre (section "Punch").
  struct PunchParameters
  {
    PunchShape          shape      = PunchShape::circle;
    double              radius     = 2.5;
    double              length     = 45;
    double              width      = 8;
    PunchContact        contact    = PunchContact::bonded;
    PunchControl        control    = PunchControl::displacement;
    double              depth      = 0.5;
    unsigned int        load_steps = 1;
    std::vector<double> forces     = {0.35, 0.5, 0.75, 1.0, 1.25, 1.5, 1.8};
    DepthErrorEstimate  depth_error_estimate = DepthErrorEstimate::none;
    double              profile_length       = 30;
    unsigned int        profile_points       = 301;
    bool                section              = true;
    bool                edge_contact         = false;
    double              edge_radius          = 0.5;
    double              contact_penalty      = 100;
    PunchTiedRegion     tied_region          = PunchTiedRegion::whole_face;
    double              friction_coefficient = 0.5;
    double              friction_penalty     = 100;

    /// Whether the point (x, y, .) lies on the punch's face (edges
    /// included, to round-off).
    bool
    covers(const Point<3> &p) const;

    /// Whether the skin node at @p p is held by the punch (Tied region):
    /// under the face, or only under its flat part.
    bool
    ties(const Point<3> &p) const;

    /// The face's area, mm^2.
    double
    area() const;

    /// The loads of the steps: depths (mm) or forces (N).
    std::vector<double>
    loads() const;

    /// Declares section "Punch", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;

  private:
    /// Declares the shape and size of the punch's face.
    void
    add_face_parameters(ParameterHandler &prm);

    /// Declares how the skin under the face is held (bonded, friction).
    void
    add_contact_parameters(ParameterHandler &prm);

    /// Declares the depths or forces of the load steps.
    void
    add_loading_parameters(ParameterHandler &prm);

    /// Declares the surface profile and the section written.
    void
    add_output_parameters(ParameterHandler &prm);

    /// Declares the rounded edge's contact and the tied region.
    void
    add_edge_contact_parameters(ParameterHandler &prm);
  };
} // namespace ssc

#endif
