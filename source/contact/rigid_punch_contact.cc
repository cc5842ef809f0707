#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <cmath>

#include <ssc/contact/rigid_punch_contact.h>

namespace ssc
{
  PunchGap
  punch_gap(const PunchGeometry &geometry, const Point<3> &x, const double face)
  {
    const double rho = geometry.edge_radius;
    const double dx = x[0] - geometry.centre[0], dy = x[1] - geometry.centre[1];
    const double r = std::hypot(dx, dy);
    const double s = r - (geometry.radius - rho); // beyond the rounding start
    const double t = x[2] - face - rho; // above the centre line of the edge
    PunchGap     gap;
    if (s <= 0.)
      {
        // the flat face: g = face - z
        gap.value       = face - x[2];
        gap.gradient[2] = -1.;
        gap.gradient[3] = 1.;
        return gap;
      }
    // derivatives of s and t with respect to q = (x, y, z, face)
    Tensor<1, 4> ds, dt;
    Tensor<2, 4> dds;
    const double e[2] = {dx / r, dy / r};
    for (unsigned int a = 0; a < 2; ++a)
      {
        ds[a] = e[a];
        for (unsigned int b = 0; b < 2; ++b)
          dds[a][b] = ((a == b ? 1. : 0.) - e[a] * e[b]) / r;
      }
    dt[2] = 1.;
    dt[3] = -1.;
    if (t >= 0.)
      {
        // the cylinder wall: g = r - R
        gap.value    = s - rho;
        gap.gradient = ds;
        gap.hessian  = dds;
        return gap;
      }
    // the rounded edge: distance from its centre line minus rho
    const double d = std::hypot(s, t);
    gap.value      = d - rho;
    gap.gradient   = (s * ds + t * dt) / d;
    gap.hessian    = (outer_product(ds, ds) + outer_product(dt, dt) + s * dds -
                   outer_product(gap.gradient, gap.gradient)) /
                  d;
    return gap;
  }


  RigidPunchContact::RigidPunchContact(
    const PunchGeometry                         &geometry,
    const double                                 penalty_factor,
    const double                                 youngs_modulus,
    const double                                 reach,
    const DoFHandler<3>                         &dof_handler,
    const Mapping<3>                            &mapping,
    const types::boundary_id                     top,
    const std::function<bool(const Point<3> &)> &held,
    std::function<types::global_dof_index()>     face_dof)
    : geometry(geometry)
    , face_dof(std::move(face_dof))
    , mpi_communicator(dof_handler.get_communicator())
  {
    const auto &fe        = dof_handler.get_fe();
    const auto  radius_of = [&](const Point<3> &X) {
      return std::hypot(X[0] - geometry.centre[0], X[1] - geometry.centre[1]);
    };
    const QGauss<2>                      quadrature(4);
    FEFaceValues<3>                      fe_face_values(mapping,
                                   fe,
                                   quadrature,
                                   update_values | update_quadrature_points |
                                     update_JxW_values);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() || face->boundary_id() != top ||
                radius_of(face->center()) > reach)
              continue;
            bool free = false;
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              free = free || !held(face->vertex(v));
            if (!free)
              continue; // held by the punch's tie
            fe_face_values.reinit(cell, f);
            cell->get_dof_indices(cell_dofs);
            Face                      contact_face;
            std::vector<unsigned int> local;
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              if (fe.has_support_on_face(i, f))
                {
                  local.push_back(i);
                  contact_face.dofs.push_back(cell_dofs[i]);
                  contact_face.components.push_back(
                    fe.system_to_component_index(i).first);
                }
            contact_face.penalty =
              penalty_factor * youngs_modulus / std::sqrt(face->measure());
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                contact_face.points.push_back(
                  fe_face_values.quadrature_point(q));
                std::vector<double> values;
                for (const unsigned int i : local)
                  values.push_back(fe_face_values.shape_value(i, q));
                contact_face.shape_values.push_back(values);
                contact_face.areas.push_back(fe_face_values.JxW(q));
              }
            faces.push_back(std::move(contact_face));
          }
  }


  std::vector<std::vector<types::global_dof_index>>
  RigidPunchContact::couplings() const
  {
    const types::global_dof_index                     height = face_dof();
    std::vector<std::vector<types::global_dof_index>> groups;
    for (const Face &face : faces)
      {
        groups.push_back(face.dofs);
        groups.back().push_back(height);
      }
    return groups;
  }


  void
  RigidPunchContact::for_each_penetration(
    const TrilinosWrappers::MPI::Vector                                     &u,
    const std::function<void(const Face &, unsigned int, const PunchGap &)> &f)
    const
  {
    const double height = u[face_dof()];
    for (const Face &face : faces)
      for (unsigned int q = 0; q < face.points.size(); ++q)
        {
          Point<3> x = face.points[q];
          for (unsigned int k = 0; k < face.dofs.size(); ++k)
            x[face.components[k]] += face.shape_values[q][k] * u[face.dofs[k]];
          const PunchGap gap = punch_gap(geometry, x, height);
          if (gap.value < 0.)
            f(face, q, gap);
        }
  }


  void
  RigidPunchContact::add_nonlinear(const TrilinosWrappers::MPI::Vector &u,
                                   const bool       with_tangent,
                                   const BlockSink &add) const
  {
    const types::global_dof_index height = face_dof();
    // the blocks of the faces, accumulated over their quadrature points
    const Face                          *current = nullptr;
    std::vector<types::global_dof_index> dofs;
    FullMatrix<double>                   matrix;
    Vector<double>                       residual;
    const auto                           flush = [&]() {
      if (current != nullptr)
        add(dofs, matrix, residual);
    };
    for_each_penetration(
      u, [&](const Face &face, const unsigned int q, const PunchGap &gap) {
        const unsigned int n = face.dofs.size();
        if (&face != current)
          {
            flush();
            current = &face;
            dofs    = face.dofs;
            dofs.push_back(height);
            matrix.reinit(n + 1, n + 1);
            residual.reinit(n + 1);
          }
        // dg/d(dof k) through x = X + sum N_k u_k and the height (last)
        std::vector<double> dg(n + 1);
        for (unsigned int k = 0; k < n; ++k)
          dg[k] = gap.gradient[face.components[k]] * face.shape_values[q][k];
        dg[n]              = gap.gradient[3];
        const auto hessian = [&](const unsigned int k, const unsigned int l) {
          const double       Nk = k < n ? face.shape_values[q][k] : 1.;
          const double       Nl = l < n ? face.shape_values[q][l] : 1.;
          const unsigned int a  = k < n ? face.components[k] : 3;
          const unsigned int b  = l < n ? face.components[l] : 3;
          return gap.hessian[a][b] * Nk * Nl;
        };
        // energy eps/2 g^2: residual eps g dg, tangent eps (dg dg + g ddg)
        const double w = face.penalty * face.areas[q];
        for (unsigned int k = 0; k <= n; ++k)
          {
            residual(k) += w * gap.value * dg[k];
            if (with_tangent)
              for (unsigned int l = 0; l <= n; ++l)
                matrix(k, l) += w * (dg[k] * dg[l] + gap.value * hessian(k, l));
          }
      });
    flush();
  }


  std::pair<double, double>
  RigidPunchContact::contact_state(const TrilinosWrappers::MPI::Vector &u) const
  {
    double area = 0, penetration = 0;
    for_each_penetration(
      u, [&](const Face &face, const unsigned int q, const PunchGap &gap) {
        area += face.areas[q];
        penetration = std::max(penetration, -gap.value);
      });
    return {Utilities::MPI::sum(area, mpi_communicator),
            Utilities::MPI::max(penetration, mpi_communicator)};
  }


  unsigned int
  RigidPunchContact::n_faces() const
  {
    return Utilities::MPI::sum(static_cast<unsigned int>(faces.size()),
                               mpi_communicator);
  }
} // namespace ssc
