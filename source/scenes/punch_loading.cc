#include <deal.II/base/function.h>

#include <array>
#include <cmath>
#include <functional>
#include <sstream>

#include <ssc/scenes/punch_loading.h>
#include <ssc/scenes/quasi_static_driver.h>
#include <ssc/scenes/support_conditions.h>

namespace ssc
{
  namespace
  {
    /// Throws unless skin surface nodes lie under the punch and, for a
    /// rectangle, the corners of its face are nodes (no cells cut).
    void
    check_punch_nodes(const PunchParameters &punch,
                      const ElasticSystem   &system,
                      const double           symmetry_factor,
                      const std::function<bool(const Point<3> &)> &on_punch)
    {
      const double a = punch.radius;
      // a punch between the surface nodes would hold nothing and report a
      // zero force; a rectangle whose edges cut through cells would press
      // on a smaller, jagged face
      const bool          rectangle = punch.shape == PunchShape::rectangle;
      unsigned int        n_under   = 0;
      std::array<bool, 4> corner_found{};
      for (const auto &cell :
           system.field().dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == BoundaryId::top)
              for (const unsigned int v : face->vertex_indices())
                {
                  const Point<3> &p = face->vertex(v);
                  n_under += on_punch(p);
                  // corners numbered by the signs of x and y
                  if (std::abs(std::abs(p[0]) - punch.length / 2) < 1e-9 &&
                      std::abs(std::abs(p[1]) - punch.width / 2) < 1e-9)
                    corner_found[(p[0] > 0) + 2 * (p[1] > 0)] = true;
                }
      const MPI_Comm communicator =
        system.field().triangulation().get_communicator();
      if (Utilities::MPI::sum(n_under, communicator) == 0)
        {
          std::ostringstream message;
          message << "Punch/Radius = " << a << " mm"
                  << (punch.tied_region == PunchTiedRegion::flat_face ?
                        " (its flat face: Radius - Edge radius = " +
                          std::to_string(a - punch.edge_radius) + " mm)" :
                        std::string())
                  << ": no mesh node of the skin surface lies under the "
                     "punch, so it would press on nothing. Refine the mesh "
                     "there (Mesh/Cell size, Mesh/Region of interest) or "
                     "enlarge the punch.";
          AssertThrow(rectangle, ExcMessage(message.str()));
        }
      if (rectangle)
        {
          unsigned int n_corners = 0; // each found on some process
          for (const bool found : corner_found)
            n_corners += Utilities::MPI::max(static_cast<unsigned int>(found),
                                             communicator);
          std::ostringstream message;
          message << "Punch/Shape = rectangle: the corners (+-"
                  << punch.length / 2 << ", +-" << punch.width / 2
                  << ") of the probe's face are not all nodes of the skin "
                     "surface, so its edges would cut through cells. Put mesh "
                     "lines there: Mesh/Core half width = Length/2, Core half "
                     "width y = Width/2 and Grading ratio > 1.";
          // a quarter model has the corner x > 0, y > 0 only
          AssertThrow(n_corners == (symmetry_factor > 1 ? 1 : 4),
                      ExcMessage(message.str()));
        }
    }


    /// The Coulomb friction on the punch's face, attached to @p system.
    std::unique_ptr<PunchFriction>
    attach_face_friction(const Parameters &parameters,
                         ElasticSystem    &system,
                         const std::function<bool(const Point<3> &)> &on_punch,
                         ConditionalOStream                          &pcout)
    {
      const PunchParameters         &punch = parameters.punch;
      std::unique_ptr<PunchFriction> face_friction =
        std::make_unique<PunchFriction>(
          punch.friction_coefficient,
          punch.friction_penalty,
          parameters.layers.layer(0).youngs_modulus,
          system.field().dof_handler(),
          system.field().mapping(),
          BoundaryId::top,
          on_punch,
          [&system]() { return system.nodal_residual(); });
      system.attach(*face_friction);
      pcout << "Punch friction: " << face_friction->n_nodes()
            << " skin nodes under the face, mu = " << punch.friction_coefficient
            << std::endl;
      return face_friction;
    }


    /// The contact of the skin with the punch's rounded edge, attached to
    /// @p system.
    std::unique_ptr<RigidPunchContact>
    attach_edge_contact(const Parameters                            &parameters,
                        ElasticSystem                               &system,
                        const std::function<bool(const Point<3> &)> &on_punch,
                        ConditionalOStream                          &pcout)
    {
      const PunchParameters &punch = parameters.punch;
      const double           a     = punch.radius;
      // the surface faces that wrapping around the edge can bring into
      // contact: up to a radius plus two edge radii beyond the rim
      const double reach = 2. * a + 2. * punch.edge_radius;
      std::unique_ptr<RigidPunchContact> contact =
        std::make_unique<RigidPunchContact>(
          PunchGeometry{Point<2>(0, 0), a, punch.edge_radius},
          punch.contact_penalty,
          parameters.layers.layer(0).youngs_modulus,
          reach,
          system.field().dof_handler(),
          system.field().mapping(),
          BoundaryId::top,
          on_punch,
          [&system]() { return system.constraints().master_dof(0); });
      system.attach(*contact);
      pcout << "Edge contact: " << contact->n_faces()
            << " surface faces within " << reach
            << " mm of the axis, edge radius " << punch.edge_radius << " mm"
            << std::endl;
      return contact;
    }
  } // namespace


  PunchLoading::PunchLoading(const Parameters   &parameters,
                             ElasticSystem      &system,
                             TimerOutput        &timer,
                             ConditionalOStream &pcout)
    : system(system)
    , by_force(parameters.punch.control == PunchControl::force)
    , symmetry_factor(parameters.mesh.symmetry_factor())
  {
    TimerOutput::Scope     t(timer, "setup");
    const PunchParameters &punch = parameters.punch;
    const auto on_punch = [punch](const Point<3> &p) { return punch.ties(p); };
    check_punch_nodes(punch, system, symmetry_factor, on_punch);
    std::vector<DirichletCondition> conditions =
      support_conditions(parameters.elasticity.sides, parameters.mesh.symmetry);
    std::vector<TiedCondition> ties;
    ComponentMask              components(3, false);
    if (punch.contact == PunchContact::bonded)
      {
        components.set(0, true);
        components.set(1, true);
      }
    // the unit load: 1 mm depth or 1 N. The tie's master is also the
    // punch's height for the edge contact; under displacement control its
    // dofs are all prescribed, so the tie only names the master.
    if (by_force || punch.edge_contact)
      ties.push_back({BoundaryId::top, 2, on_punch, Point<3>(0, 0, 0)});
    if (!by_force)
      components.set(2, true);
    if (components.n_selected_components() > 0)
      conditions.push_back({BoundaryId::top,
                            components,
                            std::make_shared<Functions::ConstantFunction<3>>(
                              std::vector<double>{0., 0., by_force ? 0. : -1.}),
                            on_punch});
    // the punch's condition: the tie (numbered after the conditions) under
    // force control, the prescribed displacement otherwise
    punch_condition = by_force ? conditions.size() : conditions.size() - 1;

    if (punch.contact == PunchContact::friction)
      face_friction = attach_face_friction(parameters, system, on_punch, pcout);
    if (punch.edge_contact)
      contact = attach_edge_contact(parameters, system, on_punch, pcout);
    system.setup(conditions, ties);
  }


  void
  PunchLoading::apply(const double load)
  {
    if (by_force)
      {
        system.constraints().apply(system.field());
        system.loads().nodal_forces = {
          {system.constraints().master_dof(0), -load / symmetry_factor}};
      }
    else
      // Newton's first update takes the punch to the new depth
      system.constraints().set_dirichlet_scale(load);
  }


  double
  PunchLoading::reaction_force()
  {
    return -symmetry_factor * system.reaction(punch_condition)[2];
  }


  double
  PunchLoading::force(const double load)
  {
    return by_force ? load : reaction_force();
  }


  double
  PunchLoading::depth(const double load) const
  {
    if (!by_force)
      return load;
    const types::global_dof_index master = system.constraints().master_dof(0);
    return -system.field().solution()[master];
  }


  void
  follow_punch_path(QuasiStaticDriver                       &driver,
                    PunchLoading                            &loading,
                    const Parameters                        &parameters,
                    const std::function<void(unsigned int)> &on_step)
  {
    const std::vector<double> loads = parameters.punch.loads();
    driver.run(
      loads,
      [&loading](const double load) { loading.apply(load); },
      loads.front() / parameters.newton.initial_steps,
      LoadDependence::right_hand_side,
      on_step);
  }
} // namespace ssc
