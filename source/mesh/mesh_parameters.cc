#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <ssc/mesh/mesh_parameters.h>

namespace ssc
{
  void
  MeshParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    add_layout_parameters(prm);
    add_cell_size_parameters(prm);
    add_o_grid_parameters(prm);
    add_region_of_interest_parameters(prm);
    prm.leave_subsection();
  }


  void
  MeshParameters::add_layout_parameters(ParameterHandler &prm)
  {
    prm.add_parameter(
      "Layout",
      layout,
      "How the lateral plane is meshed. box: a tensor-product grid of 'Cell "
      "size', graded away from a central square ('Core half width', "
      "'Grading ratio'), optionally fitted to a circle. o-grid: rings of "
      "cells around the circle of 'Fitted circle radius' (a punch edge), "
      "their radial size 'O-grid/Edge cell size' at the circle and growing "
      "by 'O-grid/Radial grading' away from it (inwards and outwards), around "
      "a small square core; the cells of the singular edge are then thin "
      "radially and few around, as a peer's graded mesh has them. Cell size, "
      "Core half width and Grading ratio are not used by the o-grid.",
      Patterns::Selection(enum_names<MeshLayout>()));
    prm.add_parameter(
      "Symmetry",
      symmetry,
      "none: mesh the whole patch. quarter: mesh only x >= 0, y >= 0 "
      "(Patch lengths stay those of the whole patch) and hold the normal "
      "displacement on the planes x = 0 and y = 0: a quarter of the DoFs for "
      "a problem symmetric about both planes (the layer thicknesses too: "
      "ssc samples them at mirrored points). Forces, stiffness and areas are "
      "reported for the whole patch. Box layout and the indentation scene "
      "without microstructure or edge contact.",
      Patterns::Selection(enum_names<MeshSymmetry>()));
    prm.add_parameter("Patch length x",
                      patch_length_x,
                      "Lateral extent of the patch in x, mm, centred at 0.",
                      Patterns::Double(0, max_patch_length));
    prm.add_parameter("Patch length y",
                      patch_length_y,
                      "Lateral extent of the patch in y, mm, centred at 0.",
                      Patterns::Double(0, max_patch_length));
  }


  void
  MeshParameters::add_cell_size_parameters(ParameterHandler &prm)
  {
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
    prm.add_parameter("Core half width y",
                      core_half_width_y,
                      "Half width (mm) of the core in y, if it differs from "
                      "Core half width (a rectangular core, e.g. the edges "
                      "of a rectangular probe: Punch/Shape = rectangle); 0: "
                      "the same as Core half width.",
                      Patterns::Double(0, 1e4));
    prm.add_parameter(
      "Core edge cell size",
      core_edge_cell_size,
      "Box layout: 0 for a uniform core; else the lateral cell size (mm) at "
      "the core's edges (e.g. a rectangular probe's edges, where the "
      "stresses are singular), growing by Grading ratio away from them, "
      "inwards up to Cell size and outwards to the patch edge; the cell "
      "heights then start at this size at the skin surface and grow by the "
      "same ratio, each layer keeping at least its Cells across.",
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
  }


  void
  MeshParameters::add_o_grid_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("O-grid");
    prm.add_parameter("Cells around",
                      o_grid_cells_around,
                      "Number of cells around the circle (a multiple of 4; "
                      "the square core has a quarter of them per side).",
                      Patterns::Integer(8, 4096));
    prm.add_parameter("Edge cell size",
                      o_grid_edge_cell_size,
                      "Radial size (mm) of the cells on either side of the "
                      "circle.",
                      Patterns::Double(0, 1e4));
    prm.add_parameter("Radial grading",
                      o_grid_radial_grading,
                      "Ratio of successive radial cell sizes away from the "
                      "circle; the size stops growing where it reaches the "
                      "spacing of the cells around (cells then stay about "
                      "square).",
                      Patterns::Double(1, 3));
    prm.add_parameter("Outer boundary",
                      o_grid_outer_boundary,
                      "Shape of the patch's lateral boundary: the square "
                      "(rectangle) of the patch lengths, or the circle of "
                      "diameter 'Patch length x' (an axisymmetric problem; "
                      "needs equal patch lengths and Elasticity/Sides free or "
                      "fixed).",
                      Patterns::Selection(enum_names<OuterBoundary>()));
    prm.add_parameter(
      "Grade in depth",
      o_grid_grade_in_depth,
      "Whether the cell heights, too, start at 'Edge cell size' at the skin "
      "surface and grow by 'Radial grading' with depth (each layer keeping "
      "at least its 'Cells across'; the layers' 'Grading' is then not "
      "used): the edge of a punch on the surface is singular in depth as "
      "much as radially.",
      Patterns::Bool());
    prm.leave_subsection();
  }


  void
  MeshParameters::add_region_of_interest_parameters(ParameterHandler &prm)
  {
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
  }


  std::string
  MeshParameters::coarsening_advice() const
  {
    std::string advice = "use a larger Mesh/";
    if (layout == MeshLayout::o_grid)
      advice += "O-grid/Edge cell size or Radial grading";
    else
      advice += std::string("Cell size, Grading ratio") +
                (core_edge_cell_size > 0 ? ", Core edge cell size" : "");
    if (global_refinements > 0)
      advice += ", fewer Mesh/Global refinements";
    if (local_refinements > 0)
      advice += ", fewer Mesh/Region of interest/Local refinements";
    return advice + " or fewer Layer stack/<layer>/Cells across";
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
    AssertThrow(core_edge_cell_size == 0 ||
                  (layout == MeshLayout::box && grading_ratio > 1 &&
                   core_edge_cell_size <= cell_size),
                ExcMessage("Mesh/Core edge cell size > 0 grades the box "
                           "layout's cells from the core's edges: it needs "
                           "Layout = box, Grading ratio > 1 and a size of "
                           "at most Cell size."));
    if (layout == MeshLayout::o_grid)
      {
        AssertThrow(fitted_circle_radius > 0,
                    ExcMessage("Mesh/Layout = o-grid needs the circle its "
                               "rings follow: set Mesh/Fitted circle radius "
                               "> 0 (mm), e.g. the punch radius."));
        AssertThrow(o_grid_cells_around % 4 == 0,
                    ExcMessage("Mesh/O-grid/Cells around = " +
                               std::to_string(o_grid_cells_around) +
                               " must be a multiple of 4."));
        AssertThrow(o_grid_edge_cell_size > 0 &&
                      o_grid_edge_cell_size <= fitted_circle_radius,
                    ExcMessage("Mesh/O-grid/Edge cell size must be positive "
                               "and at most the Fitted circle radius."));
        AssertThrow(o_grid_outer_boundary == OuterBoundary::square ||
                      patch_length_x == patch_length_y,
                    ExcMessage("Mesh/O-grid/Outer boundary = circle has the "
                               "diameter Mesh/Patch length x, which must "
                               "equal Patch length y."));
      }
  }
} // namespace ssc
