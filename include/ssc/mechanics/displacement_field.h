#ifndef ssc_mechanics_displacement_field_h
#define ssc_mechanics_displacement_field_h

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <ssc/embedding/point_locator.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The displacement of the background mesh: FE_Q(p)^3 on the
   * parallel::distributed mesh, its dofs and the solution vector with the
   * ghost entries this rank needs (the mesh's locally relevant dofs, plus
   * what the constraints add, such as the master of a tie). What can be
   * asked of a displacement lives here: values at located points, errors
   * against an exact solution, a description of where a field is large.
   */
  class DisplacementField
  {
  public:
    /// Q@p degree displacements on @p tria, the cells mapped with
    /// polynomials of @p mapping_degree (1: straight-edged; the degree
    /// places its support points on the mesh's manifolds).
    DisplacementField(const parallel::distributed::Triangulation<3> &tria,
                      const unsigned int                             degree,
                      const unsigned int mapping_degree = 1);

    /// Distributes the dofs and sizes the solution (zero).
    void
    distribute_dofs();

    /// Resizes the solution for @p relevant ghost dofs (at least the mesh's
    /// locally relevant ones), keeping its values.
    void
    set_relevant_dofs(const IndexSet &relevant);

    const DoFHandler<3> &
    dof_handler() const
    {
      return dofs;
    }

    const parallel::distributed::Triangulation<3> &
    triangulation() const
    {
      return tria;
    }

    const FESystem<3> &
    fe() const
    {
      return finite_element;
    }

    const MappingQ<3> &
    mapping() const
    {
      return cell_mapping;
    }

    const IndexSet &
    locally_owned_dofs() const
    {
      return owned_dofs;
    }

    /// The locally relevant dofs of the mesh (without what constraints
    /// add).
    const IndexSet &
    mesh_relevant_dofs() const
    {
      return mesh_relevant;
    }

    /// The solution with ghost entries.
    const TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return ghosted_solution;
    }

    /// The dofs of vertex @p v of @p cell, by displacement component.
    std::array<types::global_dof_index, 3>
    vertex_dofs(const DoFHandler<3>::active_cell_iterator &cell,
                const unsigned int                         v) const;

    /// A copy of the locally owned entries of the solution.
    TrilinosWrappers::MPI::Vector
    owned_solution() const;

    /// Replaces the solution (locally owned entries, e.g. from
    /// owned_solution(); the ghosts are updated).
    void
    set_solution(const TrilinosWrappers::MPI::Vector &owned);

    /// Displacement and its gradient at located points, on every rank
    /// (collective: each point is evaluated by the rank that owns it).
    void
    evaluate_at(const std::vector<PointLocation> &locations,
                std::vector<Tensor<1, 3>>        &displacements,
                std::vector<Tensor<2, 3>>        &gradients) const;

    /// Displacement at point @p p (on whichever rank owns it, then
    /// broadcast); throws if no rank finds it.
    Tensor<1, 3>
    point_value(const Point<3> &p) const;

    /// L2 norm and H1 seminorm of u - @p exact.
    std::pair<double, double>
    errors(const Function<3> &exact) const;

    /**
     * Where the displacement field @p du (locally owned entries, e.g. an
     * update or the change over an increment) lives: the centre and spread
     * of |du|^2 in radius from the z axis (the punch's) and in depth, the
     * shares of its radial, hoop and vertical components and its largest
     * nodal value. It tells which part of the model loses stability
     * (collective).
     */
    std::string
    describe(const TrilinosWrappers::MPI::Vector &du) const;

  private:
    const parallel::distributed::Triangulation<3> &tria;
    MPI_Comm                                       mpi_communicator;
    FESystem<3>                                    finite_element;
    MappingQ<3>                                    cell_mapping;
    DoFHandler<3>                                  dofs;
    IndexSet                                       owned_dofs;
    IndexSet                                       mesh_relevant;
    TrilinosWrappers::MPI::Vector                  ghosted_solution;
  };
} // namespace ssc

#endif
