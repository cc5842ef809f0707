#ifndef ssc_mesh_mesh_parameters_h
#define ssc_mesh_mesh_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace ssc
{
  using namespace dealii;

  /**
   * Parameters of the background hex mesh (section "Mesh"): the lateral
   * extent of the patch, the lateral cell size with optional geometric
   * grading away from a core, and refinement towards a region of interest.
   * The initial values are the defaults of the prm entries.
   */
  struct MeshParameters
  {
    double       patch_length_x     = 40;
    double       patch_length_y     = 40;
    double       cell_size          = 2;
    double       core_half_width    = 10;
    double       grading_ratio      = 1;
    unsigned int global_refinements = 0;
    /// Radius of the circle around the centre that mesh lines follow
    /// (0: none); see DiskFittingMap.
    double fitted_circle_radius = 0;

    /// Region of interest: a ring of radius roi_radius (0: a disk) around
    /// the patch centre at the skin surface, of width and depth roi_width.
    double       roi_radius        = 0;
    double       roi_width         = 5;
    double       roi_shrink        = 1;
    unsigned int local_refinements = 0;

    /// Declares section "Mesh", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;
  };
} // namespace ssc

#endif
