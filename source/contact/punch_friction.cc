#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <map>

#include <ssc/contact/punch_friction.h>

namespace ssc
{
  PunchFriction::PunchFriction(
    const double                                   coefficient,
    const double                                   penalty_factor,
    const double                                   youngs_modulus,
    const DoFHandler<3>                           &dof_handler,
    const Mapping<3>                              &mapping,
    const types::boundary_id                       top,
    const std::function<bool(const Point<3> &)>   &held,
    std::function<TrilinosWrappers::MPI::Vector()> nodal_residual)
    : coefficient(coefficient)
    , nodal_residual(std::move(nodal_residual))
    , mpi_communicator(dof_handler.get_communicator())
  {
    const FiniteElement<3> &fe = dof_handler.get_fe();
    const QGauss<2>         quadrature(fe.degree + 1);
    FEFaceValues<3>         fe_face_values(mapping,
                                   fe,
                                   quadrature,
                                   update_values | update_JxW_values);
    // k_i, assembled over the faces of all ranks at the x dofs
    const IndexSet               &owned = dof_handler.locally_owned_dofs();
    TrilinosWrappers::MPI::Vector stiffness;
    stiffness.reinit(owned,
                     DoFTools::extract_locally_relevant_dofs(dof_handler),
                     mpi_communicator,
                     true);
    std::map<types::global_dof_index, std::array<types::global_dof_index, 3>>
                                         held_nodes;
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() || face->boundary_id() != top)
              continue;
            bool reinitialised = false;
            cell->get_dof_indices(cell_dofs);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const auto [component, base] = fe.system_to_component_index(i);
                if (component != 0 || !fe.has_support_on_face(i, f) ||
                    !held(mapping.transform_unit_to_real_cell(
                      cell, fe.unit_support_point(i))))
                  continue;
                if (!reinitialised)
                  fe_face_values.reinit(cell, f);
                reinitialised            = true;
                held_nodes[cell_dofs[i]] = {
                  {cell_dofs[i],
                   cell_dofs[fe.component_to_system_index(1, base)],
                   cell_dofs[fe.component_to_system_index(2, base)]}};
                double area = 0;
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  area +=
                    fe_face_values.shape_value(i, q) * fe_face_values.JxW(q);
                stiffness[cell_dofs[i]] += penalty_factor * youngs_modulus /
                                           std::sqrt(face->measure()) * area;
              }
          }
    stiffness.compress(VectorOperation::add);
    for (const auto &[x_dof, dofs] : held_nodes)
      if (owned.is_element(x_dof))
        {
          Node node;
          node.dofs      = dofs;
          node.stiffness = stiffness[x_dof];
          // a stick point is where the friction force over k_i leaves it
          AssertThrow(node.stiffness > 0,
                      ExcMessage("Punch friction: a skin node under the "
                                 "punch has no surface area of its own (its "
                                 "shape function integrates to zero on the "
                                 "surface), so it can carry no friction; "
                                 "use Lagrange elements on undistorted "
                                 "surface faces."));
          nodes.push_back(node);
        }
  }


  std::vector<std::vector<types::global_dof_index>>
  PunchFriction::couplings() const
  {
    std::vector<std::vector<types::global_dof_index>> groups;
    for (const Node &node : nodes)
      groups.push_back({node.dofs[0], node.dofs[1]});
    return groups;
  }


  Tensor<1, 2>
  PunchFriction::slip(const Node                          &node,
                      const TrilinosWrappers::MPI::Vector &u) const
  {
    Tensor<1, 2> d;
    for (unsigned int c = 0; c < 2; ++c)
      d[c] = u[node.dofs[c]] - node.stick_point[c] - offset[c];
    return d;
  }


  std::pair<Tensor<1, 2>, bool>
  PunchFriction::force(const Node &node, const Tensor<1, 2> &d) const
  {
    const double capacity = coefficient * node.normal_force;
    if (node.stiffness * d.norm() <= capacity)
      return {node.stiffness * d, false};
    return {capacity * d / d.norm(), true};
  }


  void
  PunchFriction::add_nonlinear(const TrilinosWrappers::MPI::Vector &u,
                               const bool       with_tangent,
                               const BlockSink &add) const
  {
    FullMatrix<double> tangent(2, 2);
    Vector<double>     residual(2);
    for (const Node &node : nodes)
      {
        const Tensor<1, 2> d                  = slip(node, u);
        const auto [friction_force, slipping] = force(node, d);
        tangent                               = 0;
        if (with_tangent)
          {
            if (!slipping)
              for (unsigned int c = 0; c < 2; ++c)
                tangent(c, c) = node.stiffness;
            else
              {
                // c/|d| (I - n n^T): the cone's tangent, no stiffness along
                // the slip
                const double       length = d.norm();
                const Tensor<1, 2> n      = d / length;
                const double scale = coefficient * node.normal_force / length;
                for (unsigned int a = 0; a < 2; ++a)
                  for (unsigned int b = 0; b < 2; ++b)
                    tangent(a, b) = scale * ((a == b ? 1. : 0.) - n[a] * n[b]);
              }
          }
        for (unsigned int c = 0; c < 2; ++c)
          residual(c) = friction_force[c];
        add({node.dofs[0], node.dofs[1]}, tangent, residual);
      }
  }


  bool
  PunchFriction::accept(const TrilinosWrappers::MPI::Vector &u)
  {
    // the body presses on the punch where the vertical residual is negative
    const TrilinosWrappers::MPI::Vector residual = nodal_residual();
    std::vector<double>                 normal_forces;
    double                              change = 0, total = 0;
    for (const Node &node : nodes)
      {
        normal_forces.push_back(std::max(-residual[node.dofs[2]], 0.));
        change += std::abs(normal_forces.back() - node.normal_force);
        total += normal_forces.back();
      }
    change = Utilities::MPI::sum(change, mpi_communicator);
    total  = Utilities::MPI::sum(total, mpi_communicator);
    ++passes;
    const bool settled = change <= settled_change * total;
    if (!settled && passes < max_passes)
      {
        for (unsigned int i = 0; i < nodes.size(); ++i)
          nodes[i].normal_force = normal_forces[i];
        return false;
      }
    passes = 0;

    // the state the increment was solved with, then the stick points with
    // its normal forces
    FrictionState state;
    for (Node &node : nodes)
      {
        const Tensor<1, 2> d                  = slip(node, u);
        const auto [friction_force, slipping] = force(node, d);
        if (node.normal_force <= 0)
          ++state.free;
        else if (slipping)
          ++state.slipping;
        else
          ++state.sticking;
        state.tangential_force += friction_force;
        state.normal_force += node.normal_force;
        // the elastic part of the slip is what is left of d
        node.stick_point += d - friction_force / node.stiffness;
      }
    last_state.sticking = Utilities::MPI::sum(state.sticking, mpi_communicator);
    last_state.slipping = Utilities::MPI::sum(state.slipping, mpi_communicator);
    last_state.free     = Utilities::MPI::sum(state.free, mpi_communicator);
    last_state.tangential_force =
      Utilities::MPI::sum(state.tangential_force, mpi_communicator);
    last_state.normal_force =
      Utilities::MPI::sum(state.normal_force, mpi_communicator);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      nodes[i].normal_force = nodes[i].accepted_normal_force = normal_forces[i];
    return true;
  }


  void
  PunchFriction::reject()
  {
    for (Node &node : nodes)
      node.normal_force = node.accepted_normal_force;
    passes = 0;
  }


  void
  PunchFriction::set_offset(const Tensor<1, 2> &new_offset)
  {
    offset = new_offset;
  }


  unsigned int
  PunchFriction::n_nodes() const
  {
    return Utilities::MPI::sum(static_cast<unsigned int>(nodes.size()),
                               mpi_communicator);
  }


  double
  PunchFriction::total_stiffness() const
  {
    double total = 0;
    for (const Node &node : nodes)
      total += node.stiffness;
    return Utilities::MPI::sum(total, mpi_communicator);
  }
} // namespace ssc
