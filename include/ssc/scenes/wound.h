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
   * The outline of an incision's wound at the skin surface after the
   * tissue around it has moved: its two lips (the edges where the cut's
   * faces meet the skin surface, which coincide before loading) and the
   * measures surgeons and the cadaver studies use.
   */
  struct WoundShape
  {
    /// The planned cut, mm, and the direction it runs along (0 x, 1 y).
    double       planned_length = 0;
    unsigned int direction      = 0;
    /// The widest opening: the largest distance between the two lips'
    /// points of the same reference position, mm.
    double gap_mm = 0;
    /// The area between the lips, projected on the skin plane, mm^2.
    double area_mm2 = 0;
    /// The distance between the cut's two ends after loading, mm.
    double length_mm = 0;
    /// length_mm / gap_mm: the wound's slenderness.
    double aspect_ratio = 0;
    /// The angle of the wound's long axis (end to end) from x, degrees in
    /// [0, 180).
    double orientation_deg = 0;
    /// Lip points, sorted by side and t.
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
