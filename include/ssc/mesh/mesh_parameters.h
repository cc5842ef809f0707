#ifndef ssc_mesh_mesh_parameters_h
#define ssc_mesh_mesh_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <ssc/base/enum_table.h>

namespace ssc
{
  using namespace dealii;

  /// How the lateral (x, y) plane is meshed.
  enum class MeshLayout
  {
    /// A tensor-product grid, graded away from a central square.
    box,
    /// Rings of cells around a circle (a punch edge), graded radially
    /// towards it, around a small square core (see OGrid).
    o_grid
  };

  constexpr std::array<std::pair<MeshLayout, const char *>, 2>
  enum_table(MeshLayout)
  {
    return {{{MeshLayout::box, "box"}, {MeshLayout::o_grid, "o-grid"}}};
  }

  /// Which part of a patch symmetric about the planes x = 0 and y = 0 is
  /// meshed.
  enum class MeshSymmetry
  {
    /// The whole patch.
    none,
    /// The quarter x >= 0, y >= 0, with the normal displacement held on
    /// the planes x = 0 and y = 0.
    quarter
  };

  constexpr std::array<std::pair<MeshSymmetry, const char *>, 2>
  enum_table(MeshSymmetry)
  {
    return {{{MeshSymmetry::none, "none"}, {MeshSymmetry::quarter, "quarter"}}};
  }

  /// Outer boundary of an o-grid patch.
  enum class OuterBoundary
  {
    square,
    circle
  };

  constexpr std::array<std::pair<OuterBoundary, const char *>, 2>
  enum_table(OuterBoundary)
  {
    return {
      {{OuterBoundary::square, "square"}, {OuterBoundary::circle, "circle"}}};
  }

  /**
   * Parameters of the background hex mesh (section "Mesh"): the lateral
   * extent of the patch, the lateral cell size with optional geometric
   * grading away from a core, and refinement towards a region of interest.
   * The initial values are the defaults of the prm entries.
   */
  struct MeshParameters
  {
    MeshLayout   layout   = MeshLayout::box;
    MeshSymmetry symmetry = MeshSymmetry::none;
    /// The largest patch length ssc accepts, mm.
    static constexpr double max_patch_length = 1e4;

    double patch_length_x  = 40;
    double patch_length_y  = 40;
    double cell_size       = 2;
    double core_half_width = 10;
    /// 0: the same as core_half_width.
    double core_half_width_y = 0;
    /// 0: a uniform core.
    double       core_edge_cell_size = 0;
    double       grading_ratio       = 1;
    unsigned int global_refinements  = 0;
    /// Radius of the circle around the centre that mesh lines follow
    /// (0: none); see DiskFittingMap.
    double fitted_circle_radius = 0;

    /// O-grid (layout o-grid): cells around the circle (a multiple of 4),
    /// radial size of the cells at the circle, growth ratio of the radial
    /// size away from it, the shape of the patch's outer boundary, and
    /// whether cell heights grow the same way from the skin surface.
    unsigned int  o_grid_cells_around   = 32;
    double        o_grid_edge_cell_size = 0.2;
    double        o_grid_radial_grading = 1.3;
    OuterBoundary o_grid_outer_boundary = OuterBoundary::square;
    bool          o_grid_grade_in_depth = true;

    /// Region of interest: a ring of radius roi_radius (0: a disk) around
    /// the patch centre at the skin surface, of width and depth roi_width.
    double       roi_radius        = 0;
    double       roi_width         = 5;
    double       roi_shrink        = 1;
    unsigned int local_refinements = 0;

    /// How many copies of the meshed part make the whole patch (1 or 4):
    /// forces and areas of the whole patch are this times the model's.
    double
    symmetry_factor() const
    {
      return symmetry == MeshSymmetry::quarter ? 4. : 1.;
    }

    /// Half width (mm) of the core in direction @p d (0: x, 1: y).
    double
    core_half_width_in(const unsigned int d) const
    {
      return (d == 1 && core_half_width_y > 0) ? core_half_width_y :
                                                 core_half_width;
    }

    /// What to change for a coarser mesh, naming only the parameters
    /// that refine this one (for the messages of the size limits).
    std::string
    coarsening_advice() const;

    /// Declares section "Mesh", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;

  private:
    /// Declares Layout, Symmetry and the patch lengths (in section "Mesh").
    void
    add_layout_parameters(ParameterHandler &prm);

    /// Declares the lateral cell sizes, their grading and the refinements.
    void
    add_cell_size_parameters(ParameterHandler &prm);

    /// Declares subsection "O-grid" (the rings around the fitted circle).
    void
    add_o_grid_parameters(ParameterHandler &prm);

    /// Declares subsection "Region of interest" (local refinement).
    void
    add_region_of_interest_parameters(ParameterHandler &prm);
  };
} // namespace ssc

#endif
