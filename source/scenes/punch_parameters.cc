#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ssc/scenes/punch_parameters.h>

namespace ssc
{
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
  PunchParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Punch");
    prm.declare_entry("Radius",
                      "2.5",
                      Patterns::Double(0),
                      "Radius a of the rigid flat cylindrical punch, mm "
                      "(the forearm studies use a 5 mm diameter).");
    prm.declare_entry("Contact",
                      "bonded",
                      Patterns::Selection("bonded|frictionless"),
                      "bonded: the skin under the punch moves with it (no "
                      "slip); frictionless: only the vertical displacement "
                      "is the punch's, the skin slides freely under it "
                      "(Sneddon 1965).");
    prm.declare_entry("Control",
                      "displacement",
                      Patterns::Selection("displacement|force"),
                      "displacement: the depth is prescribed (Depth, Load "
                      "steps) and the force is the reaction; force: the "
                      "forces are prescribed (Forces) and the depth is "
                      "computed, the vertical displacements under the punch "
                      "being tied to one master unknown.");
    prm.declare_entry("Depth",
                      "0.5",
                      Patterns::Double(0),
                      "Indentation depth at the last load step, mm "
                      "(displacement control).");
    prm.declare_entry("Load steps",
                      "1",
                      Patterns::Integer(1, 1000),
                      "Number of equal depth increments (displacement "
                      "control).");
    prm.declare_entry("Forces",
                      "0.35, 0.5, 0.75, 1.0, 1.25, 1.5, 1.8",
                      Patterns::List(Patterns::Double(0)),
                      "Punch forces of the load steps, N, increasing (force "
                      "control); the forearm measurements span 0.35-1.8 N.");
    prm.declare_entry("Profile length",
                      "30",
                      Patterns::Double(0),
                      "Length (mm) of the line y = 0 through the punch "
                      "centre along which the surface displacement u_z is "
                      "written (surface_profile.csv); 0: none.");
    prm.declare_entry("Profile points",
                      "301",
                      Patterns::Integer(2, 100000),
                      "Points on that line.");
    prm.declare_entry("Section",
                      "true",
                      Patterns::Bool(),
                      "Write the displacement and von Mises stress on the "
                      "vertical plane y = 0 (section.csv, last step).");
    prm.declare_entry(
      "Edge contact",
      "false",
      Patterns::Bool(),
      "Finite strain: frictionless penalty contact of the skin beside the "
      "punch with the punch's rounded edge and face, so that the skin pulled "
      "down around the punch wraps its edge instead of passing through it. "
      "Without it a frictionless punch loses the support of its rim at a "
      "few mm depth and Newton stalls (benchmarks/README.md).");
    prm.declare_entry("Edge radius",
                      "0.5",
                      Patterns::Double(0),
                      "Radius (mm) of the rounding of the punch's bottom "
                      "edge (Edge contact); at most the punch radius.");
    prm.declare_entry("Contact penalty",
                      "100",
                      Patterns::Double(0),
                      "Penalty factor of the edge contact: the contact "
                      "pressure is (factor) E / h times the penetration, E "
                      "the top layer's Young's modulus and h the size of "
                      "the surface face, so the skin penetrates about "
                      "h/(factor) at the contact pressure E.");
    prm.leave_subsection();
  }


  void
  PunchParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Punch");
    radius     = prm.get_double("Radius");
    contact    = prm.get("Contact") == "frictionless" ?
                   PunchContact::frictionless :
                   PunchContact::bonded;
    control    = prm.get("Control") == "force" ? PunchControl::force :
                                                 PunchControl::displacement;
    depth      = prm.get_double("Depth");
    load_steps = prm.get_integer("Load steps");
    forces     = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Forces")));
    profile_length  = prm.get_double("Profile length");
    profile_points  = prm.get_integer("Profile points");
    section         = prm.get_bool("Section");
    edge_contact    = prm.get_bool("Edge contact");
    edge_radius     = prm.get_double("Edge radius");
    contact_penalty = prm.get_double("Contact penalty");
    prm.leave_subsection();
    AssertThrow(!edge_contact || (edge_radius > 0 && edge_radius <= radius),
                ExcMessage("Punch/Edge radius must be positive and at most "
                           "Punch/Radius."));
    AssertThrow(!edge_contact || contact_penalty > 0,
                ExcMessage("Punch/Contact penalty must be positive."));
    AssertThrow(radius > 0, ExcMessage("Punch/Radius must be positive (mm)."));
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
    else
      AssertThrow(depth > 0,
                  ExcMessage("Punch/Depth must be positive (mm) under "
                             "displacement control."));
  }
} // namespace ssc
