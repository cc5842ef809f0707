#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

#include <ssc/mesh/mesh_parameters.h>

namespace ssc
{
  void
  MeshParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.add_parameter("Patch length x",
                      patch_length_x,
                      "Lateral extent of the patch in x, mm, centred at 0.",
                      Patterns::Double(0, 1e4));
    prm.add_parameter("Patch length y",
                      patch_length_y,
                      "Lateral extent of the patch in y, mm, centred at 0.",
                      Patterns::Double(0, 1e4));
    prm.add_parameter("Cell size",
                      cell_size,
                      "Lateral size of the background hexahedra in the core "
                      "of the patch on the coarsest mesh, mm (Herlin et al. "
                      "2014 used about 2 mm).",
                      Patterns::Double(0, 1e4));
    prm.add_parameter("Core half width",
                      core_half_width,
                      "Half width (mm) of the central square in which cells "
                      "have the lateral 'Cell size'; outside it they grow by "
                      "'Grading ratio' per cell towards the patch edge.",
                      Patterns::Double(0, 1e4));
    prm.add_parameter("Grading ratio",
                      grading_ratio,
                      "Growth ratio of the lateral cell size outside the "
                      "core (1 = uniform mesh).",
                      Patterns::Double(1, 3));
    prm.add_parameter("Global refinements",
                      global_refinements,
                      "Uniform refinements of the coarse mesh (each halves "
                      "every cell size, in the layers too).",
                      Patterns::Integer(0, 8));
    prm.add_parameter(
      "Fitted circle radius",
      fitted_circle_radius,
      "Radius a (mm) of a circle around the patch centre that mesh lines "
      "follow exactly, e.g. the edge of a punch (0: none). The square "
      "|x|, |y| <= a of the Cartesian mesh is mapped onto the disk r <= a and "
      "blended back to the undistorted mesh at |x|, |y| = 2a, so a must be "
      "on a mesh line of the refined mesh (a multiple of the core cell size "
      "after refinement, measured from the patch centre).",
      Patterns::Double(0, 1e4));
    prm.enter_subsection("Region of interest");
    prm.add_parameter("Ring radius",
                      roi_radius,
                      "Radius (mm) of the ring around the patch centre, at "
                      "the skin surface, towards which the mesh is refined "
                      "(the edge of a punch, say); 0 refines towards the "
                      "centre line instead.",
                      Patterns::Double(0, 1e4));
    prm.add_parameter("Width",
                      roi_width,
                      "Lateral and vertical reach (mm) of the refined region "
                      "around the ring (or the centre line).",
                      Patterns::Double(0, 1e4));
    prm.add_parameter("Shrink factor",
                      roi_shrink,
                      "The width is multiplied by this factor after each "
                      "local refinement (1: the same region every time; 0.5: "
                      "geometric refinement towards a singular edge).",
                      Patterns::Double(0.1, 1));
    prm.add_parameter("Local refinements",
                      local_refinements,
                      "Number of local refinements of the cells touching the "
                      "region (hanging nodes are constrained).",
                      Patterns::Integer(0, 20));
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  MeshParameters::check() const
  {
    AssertThrow(patch_length_x > 0 && patch_length_y > 0,
                ExcMessage("Mesh/Patch length x and y must be positive (mm)."));
    AssertThrow(cell_size > 0 &&
                  cell_size <= std::max(patch_length_x, patch_length_y),
                ExcMessage("Mesh/Cell size must be positive and not larger "
                           "than the patch."));
    AssertThrow(4 * fitted_circle_radius <
                  std::min(patch_length_x, patch_length_y),
                ExcMessage("Mesh/Fitted circle radius: the fitted circle "
                           "and its blending zone (twice the radius) must "
                           "lie inside the patch."));
  }
} // namespace ssc
