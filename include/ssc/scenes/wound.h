#ifndef ssc_scenes_wound_h
#define ssc_scenes_wound_h

#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <vector>

#include <ssc/mechanics/displacement_field.h>
#include <ssc/mesh/incision.h>

namespace ssc
{
  /// One lip point of a wound: the point of the cut's surface edge at
  /// reference position t along the cut, on one side, where it went.
  struct WoundLipPoint
  {
    /// -1 or +1: the side of the cut.
    int      side;
    double   t;
    Point<3> position;
  };

  /**
   * The outline of a wound at the skin surface after the
   * tissue around it has moved: an incision's two lips (the edges where
   * the cut's faces meet the skin surface, which coincide before loading)
   * or an excision's rim, and the measures surgeons and the cadaver
   * studies use.
   */
  struct WoundShape
  {
    /// The planned cut: its shape, length (the disc's diameter), mm, and
    /// the direction a line runs along (0 x, 1 y).
    Incision::Shape shape          = Incision::Shape::line;
    double          planned_length = 0;
    /// An ellipse's planned short axis, mm.
    double       planned_width = 0;
    unsigned int direction     = 0;
    /// An excision's planned area (the rim's polygon before loading), mm^2.
    double planned_area_mm2 = 0;
    /// An excision's area change, per cent of the planned area.
    double area_change_pct = 0;
    /// The widest opening: the largest distance between the two lips'
    /// points of the same reference position, mm; of an excision, the
    /// short axis of the ellipse with the rim's area and second moments.
    double gap_mm = 0;
    /// The area between the lips (inside the rim), projected on the skin
    /// plane, mm^2.
    double area_mm2 = 0;
    /// The distance between the cut's two ends after loading, mm; of an
    /// excision, the long axis of that ellipse.
    double length_mm = 0;
    /// length_mm / gap_mm: the wound's slenderness.
    double aspect_ratio = 0;
    /// The angle of the wound's long axis (end to end, or the ellipse's)
    /// from x, degrees in [0, 180).
    double orientation_deg = 0;
    /// Lip points, sorted by side and t (an excision's rim: side 0, t its
    /// angle in the reference).
    std::vector<WoundLipPoint> lips;

    /// The wound's entry of summary.json.
    nlohmann::ordered_json
    to_json() const;

    /// Lines "side,t,x,y,z" (with a header): the outline for the plots.
    std::string
    lips_csv() const;
  };

  /**
   * Measures the wound of @p incision on @p field's current solution: the
   * surface vertices of the cut's faces (BoundaryId::cut) on both sides,
   * collected from every rank (collective).
   */
  WoundShape
  measure_wound(const DisplacementField &field, const Incision &incision);
} // namespace ssc

#endif
