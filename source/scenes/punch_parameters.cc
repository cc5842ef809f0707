#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <string>

#include <ssc/scenes/punch_parameters.h>

namespace ssc
{
  bool
  PunchParameters::covers(const Point<3> &p) const
  {
    if (shape == PunchShape::circle)
      return std::hypot(p[0], p[1]) <= radius * (1. + 1e-10);
    return std::abs(p[0]) <= length / 2 * (1. + 1e-10) &&
           std::abs(p[1]) <= width / 2 * (1. + 1e-10);
  }


  bool
  PunchParameters::ties(const Point<3> &p) const
  {
    if (tied_region == PunchTiedRegion::whole_face)
      return covers(p);
    return std::hypot(p[0], p[1]) <= (radius - edge_radius) * (1. + 1e-10);
  }


  double
  PunchParameters::area() const
  {
    return shape == PunchShape::circle ? M_PI * radius * radius :
                                         length * width;
  }


  std::vector<double>
  PunchParameters::loads() const
  {
    if (control == PunchControl::force)
      return forces;
    std::vector<double> depths;
    for (unsigned int step = 1; step <= load_steps; ++step)
      depths.push_back(depth * step / load_steps);
    return depths;
  }


  void
  PunchParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Punch");
    add_face_parameters(prm);
    add_contact_parameters(prm);
    add_loading_parameters(prm);
    add_output_parameters(prm);
    add_edge_contact_parameters(prm);
    prm.leave_subsection();
  }


  void
  PunchParameters::add_face_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Shape",
                      shape,
                      "circle: a flat cylindrical punch of radius Radius; "
                      "rectangle: a flat face Length (along x) by Width "
                      "(along y), such as an ultrasound probe's (the MULTIS "
                      "probes: 45 x 8 and 45 x 15 mm, data/multis). A "
                      "rectangle needs mesh lines along its edges (box "
                      "layout; e.g. Mesh/Core half width = Length/2 and "
                      "Core half width y = Width/2).");
    prm.add_parameter("Radius",
                      radius,
                      "Radius a of the rigid flat cylindrical punch, mm "
                      "(the forearm studies use a 5 mm diameter).",
                      Patterns::Double(0));
    prm.add_parameter("Length",
                      length,
                      "Length of a rectangular face along x, mm.",
                      Patterns::Double(0));
    prm.add_parameter("Width",
                      width,
                      "Width of a rectangular face along y, mm.",
                      Patterns::Double(0));
  }


  void
  PunchParameters::add_contact_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Contact",
                      contact,
                      "bonded: the skin under the punch moves with it (no "
                      "slip); frictionless: only the vertical displacement "
                      "is the punch's, the skin slides freely under it "
                      "(Sneddon 1965); friction: the vertical displacement "
                      "is the punch's and the skin sticks to the face until "
                      "the shear force at a node reaches Friction "
                      "coefficient times its normal force, then slips "
                      "(Coulomb; finite strain only).");
    prm.add_parameter(
      "Friction coefficient",
      friction_coefficient,
      "Coulomb's coefficient mu between the punch and the skin (Contact = "
      "friction). Dry skin on steel or glass measures 0.2-0.8 in vivo, "
      "rising with moisture (Derler and Gerhardt, Tribol Lett 45:1, 2012).",
      Patterns::Double(0));
    prm.add_parameter(
      "Friction penalty",
      friction_penalty,
      "Stick stiffness of the regularised friction (Contact = friction): a "
      "node's tangential spring is (factor) E / h times its share of the "
      "surface area, E the top layer's Young's modulus and h the face size, "
      "so a sticking node slips elastically about h/(factor) at a shear "
      "traction E. At most 1e6: a stiffer spring slips less than h/1e6 but "
      "leaves the tangent too ill-conditioned for a meaningful update.",
      Patterns::Double(0, 1e6));
  }


  void
  PunchParameters::add_loading_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Control",
                      control,
                      "displacement: the depth is prescribed (Depth, Load "
                      "steps) and the force is the reaction; force: the "
                      "forces are prescribed (Forces) and the depth is "
                      "computed, the vertical displacements under the punch "
                      "being tied to one master unknown.");
    prm.add_parameter("Depth",
                      depth,
                      "Indentation depth at the last load step, mm "
                      "(displacement control).",
                      Patterns::Double(0));
    prm.add_parameter("Load steps",
                      load_steps,
                      "Number of equal depth increments (displacement "
                      "control).",
                      Patterns::Integer(1, 1000));
    prm.add_parameter("Forces",
                      forces,
                      "Punch forces of the load steps, N, increasing (force "
                      "control); the forearm measurements span 0.35-1.8 N.",
                      Patterns::List(Patterns::Double(0)));
    prm.add_parameter(
      "Depth error estimate",
      depth_error_estimate,
      "How the run itself estimates the discretisation error of the depth "
      "at each of the Forces (force control), written as "
      "depth_error_estimate_mm (signed: the converged depth minus this one) "
      "and depth_uncertainty_mm (its size) in summary.json and drawn as "
      "error bars. coarser mesh: the whole load path solved a second time "
      "on the mesh with one global refinement fewer (Mesh/Global "
      "refinements >= 1; same lobules, septa and ligaments), Richardson's "
      "(depth - coarser depth) / (2^1.5 - 1); costs about an eighth of the "
      "scene's solve. enriched degree (Elasticity/Degree = 1): one Newton "
      "step of Q2-P0 (Q2 with the cell's mean dilatation) on the same mesh "
      "from each converged state; exact for linear layers (the Q2-P0 depth "
      "minus this one); at finite strain not given (null) where the Q2-P0 "
      "tangent at the state is indefinite, as it is for the forearm scene. "
      "none: no estimate.");
  }


  void
  PunchParameters::add_output_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Profile length",
                      profile_length,
                      "Length (mm) of the line y = 0 through the punch "
                      "centre along which the surface displacement u_z is "
                      "written (surface_profile.csv); 0: none.",
                      Patterns::Double(0));
    prm.add_parameter("Profile points",
                      profile_points,
                      "Points on that line.",
                      Patterns::Integer(2, 100000));
    prm.add_parameter("Section",
                      section,
                      "Write the displacement and von Mises stress on the "
                      "vertical plane y = 0 (section.csv, last step).");
  }


  void
  PunchParameters::add_edge_contact_parameters(ParameterHandler &prm)
  {
    prm.add_parameter(
      "Edge contact",
      edge_contact,
      "Finite strain: frictionless penalty contact of the skin beside the "
      "punch with the punch's rounded edge and face, so that the skin pulled "
      "down around the punch wraps its edge instead of passing through it. "
      "Without it a frictionless punch loses the support of its rim at a "
      "few mm depth and Newton stalls (benchmarks/README.md).");
    prm.add_parameter("Edge radius",
                      edge_radius,
                      "Radius (mm) of the rounding of the punch's bottom "
                      "edge (Edge contact); at most the punch radius.",
                      Patterns::Double(0));
    prm.add_parameter(
      "Tied region",
      tied_region,
      "The skin nodes the punch holds (Contact: all components bonded, or "
      "the vertical one frictionless). whole face: every node under the "
      "punch's Radius, so its rim is a sharp edge (singular at finite "
      "strain) whatever the Edge radius. flat face: only the nodes under the "
      "flat part of the face, r <= Radius - Edge radius; the skin under the "
      "rounding is carried by the Edge contact alone and wraps the edge as on "
      "a real indenter. Needs Edge contact; put a mesh circle there "
      "(Mesh/Fitted circle radius = Radius - Edge radius).");
    prm.add_parameter("Contact penalty",
                      contact_penalty,
                      "Penalty factor of the edge contact: the contact "
                      "pressure is (factor) E / h times the penetration, E "
                      "the top layer's Young's modulus and h the size of "
                      "the surface face, so the skin penetrates about "
                      "h/(factor) at the contact pressure E. At most 1e6: a "
                      "stiffer penalty penetrates less than h/1e6 but leaves "
                      "the tangent too ill-conditioned for a meaningful "
                      "update.",
                      Patterns::Double(0, 1e6));
  }


  void
  PunchParameters::check() const
  {
    AssertThrow(!edge_contact || (edge_radius > 0 && edge_radius <= radius),
                ExcMessage("Punch/Edge radius must be positive and at most "
                           "Punch/Radius."));
    AssertThrow(!edge_contact || contact_penalty > 0,
                ExcMessage("Punch/Contact penalty must be positive."));
    AssertThrow(radius > 0, ExcMessage("Punch/Radius must be positive (mm)."));
    AssertThrow(contact != PunchContact::friction || friction_penalty > 0,
                ExcMessage("Punch/Friction penalty must be positive."));
    AssertThrow(tied_region == PunchTiedRegion::whole_face ||
                  (edge_contact && edge_radius < radius),
                ExcMessage("Punch/Tied region = flat face leaves the skin "
                           "under the rounded edge to the edge contact: it "
                           "needs Punch/Edge contact = true and an Edge "
                           "radius smaller than the Radius."));
    AssertThrow(shape == PunchShape::circle || (length > 0 && width > 0),
                ExcMessage("Punch/Length and Width must be positive (mm)."));
    AssertThrow(shape == PunchShape::circle || !edge_contact,
                ExcMessage("Punch/Edge contact models the rounded edge of a "
                           "cylindrical punch: use it with Punch/Shape = "
                           "circle."));
    if (control == PunchControl::force)
      {
        AssertThrow(!forces.empty(),
                    ExcMessage("Punch/Forces is empty: force control needs "
                               "at least one force."));
        for (unsigned int k = 0; k < forces.size(); ++k)
          AssertThrow(forces[k] > 0 && (k == 0 || forces[k] > forces[k - 1]),
                      ExcMessage("Punch/Forces must be positive and "
                                 "increasing (N)."));
      }
    if (control == PunchControl::displacement)
      AssertThrow(depth > 0,
                  ExcMessage("Punch/Depth must be positive (mm) under "
                             "displacement control."));
  }
} // namespace ssc
