#ifndef ssc_mesh_background_mesh_h
#define ssc_mesh_background_mesh_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <memory>
#include <vector>

#include <ssc/base/resource_limits.h>
#include <ssc/mesh/incision.h>
#include <ssc/mesh/layer_manifold.h>
#include <ssc/mesh/layer_stack.h>
#include <ssc/mesh/mesh_parameters.h>

namespace ssc
{
  /// Boundary ids of the patch (deal.II's colorized box numbering), and
  /// the two faces of an incision (see Incision).
  namespace BoundaryId
  {
    constexpr types::boundary_id x_min = 0, x_max = 1, y_min = 2, y_max = 3,
                                 bottom = 4, top = 5, cut = 6;
  } // namespace BoundaryId

  /**
   * The hexahedral background mesh of the whole layer stack: a patch
   * [-Lx/2, Lx/2] x [-Ly/2, Ly/2] conforming to every layer interface
   * (material_id = layer index, 0 = skin), with the LayerManifold attached so
   * that refinement keeps the interfaces exact.
   */
  class BackgroundMesh
  {
  public:
    /// The mesh of @p layers as @p parameters say, refused beyond the
    /// cell count of @p limits. With @p multigrid_levels, p4est keeps the
    /// refinement levels on every rank (the geometric multigrid
    /// preconditioner needs them; they cost level ghost cells and change
    /// the partition's constraints, so only then), and the coarse cells are
    /// numbered column by column (see order_columns()). A non-empty
    /// @p incision splits the mesh along it (box layout only).
    BackgroundMesh(const LayerStack     &layers,
                   const MeshParameters &parameters,
                   const MPI_Comm        mpi_communicator,
                   const ResourceLimits &limits           = ResourceLimits(),
                   const bool            multigrid_levels = false,
                   const Incision       &incision         = Incision());

    /// Builds the coarse mesh and applies global and local refinement;
    /// throws, naming the parameter, if a layer's thickness is out of
    /// range at a vertex or the mesh would exceed Limits/Max cells.
    void
    build();

    /// Cells of the coarse mesh times 8 per global refinement (before any
    /// local refinement): the size of the mesh before it is built.
    static double
    estimated_cells(const LayerStack &layers, const MeshParameters &parameters);

    parallel::distributed::Triangulation<3> &
    triangulation()
    {
      return tria;
    }

    const parallel::distributed::Triangulation<3> &
    triangulation() const
    {
      return tria;
    }

    /// Polynomial degree of the cell mapping that finite elements of
    /// @p fe_degree need on this mesh: the o-grid's circles (the punch
    /// edge) are curved, and a polygon through its vertices would shrink
    /// the punch's effective radius by (pi / Cells around)^2 / 3 (0.3 % at
    /// 32 cells around), more than a Q2 solution's error, so it is
    /// isoparametric; the box is straight-edged (its curved layer interfaces
    /// keep the linear map, as they always have).
    unsigned int
    mapping_degree(const unsigned int fe_degree) const
    {
      return parameters.layout == MeshLayout::o_grid ? fe_degree : 1;
    }

    /// Symmetric cell sizes over [-L/2, L/2]: uniform of size <= h inside
    /// the core, growing geometrically by @p ratio outside it; with an
    /// @p edge_size > 0, graded from that size at the core's edges both
    /// ways (inwards up to h).
    static std::vector<double>
    graded_steps(const double L,
                 const double h,
                 const double core_half_width,
                 const double ratio,
                 const double edge_size = 0);

    /// The box layout's cell sizes along x (@p direction 0) or y (1): over
    /// the whole patch, or from the centre outwards for a quarter.
    static std::vector<double>
    lateral_steps(const MeshParameters &parameters,
                  const unsigned int    direction);

    /// Cell heights through the stack in the chart (each layer of unit
    /// height), from the bottom up: each layer's Cells across and Grading,
    /// or, for an o-grid graded in depth, a geometric sequence from the
    /// O-grid's Edge cell size at the skin surface.
    static std::vector<double>
    vertical_steps(const LayerStack &layers, const MeshParameters &parameters);

  private:
    /// The o-grid (Mesh/Layout = o-grid) extruded through the chart's
    /// vertical @p z_steps, with the box's boundary ids.
    void
    extrude_o_grid(const std::vector<double> &z_steps,
                   Triangulation<3>          &coarse) const;

    /// Manifold id 1 (the polar layer chart) for the cells, faces and lines
    /// of the o-grid whose vertices all lie on its circles.
    void
    set_polar_manifold_ids(Triangulation<3> &coarse) const;

    void
    refine_region_of_interest();

    /// The coarse cells renumbered column by column: by the (x, y) of
    /// their centres, then z. p4est partitions the mesh along an order of
    /// the coarse cells that deal.II derives from this one (a hierarchical
    /// reordering of their graph), so fewer columns of cells are split
    /// between ranks, and fewer of the vertical lines that the multigrid's
    /// smoother solves whole have to be gathered from two ranks: 72
    /// instead of 425 on prm/punch_large.prm with 2 refinements on 2 ranks
    /// (boxes come from deal.II with z as the slowest index).
    static void
    order_columns(Triangulation<3> &coarse);

    /// Throws unless mesh vertices lie on the fitted circle at the surface.
    void
    check_fitted_circle() const;

    /// Throws, naming the layer, unless every layer's thickness is in range
    /// at the vertices, edge midpoints and cell centres of the locally
    /// owned cells (collective): every point where the mapping evaluates
    /// the layer map. A dip narrower than the cells between them is not in
    /// the discrete model and is not seen.
    void
    check_thickness_at_vertices() const;

    const LayerStack                       &layers;
    const MeshParameters                   &parameters;
    const ResourceLimits                    limits;
    const bool                              multigrid_levels;
    const Incision                          incision;
    parallel::distributed::Triangulation<3> tria;
  };
} // namespace ssc

#endif
