#ifndef ssc_scenes_closure_h
#define ssc_scenes_closure_h

#include <nlohmann/json.hpp>

#include <vector>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/mechanics/suture_ties.h>
#include <ssc/mesh/incision.h>

namespace ssc
{
  /**
   * The interrupted sutures that close the elliptic excision @p incision:
   * one every @p spacing mm along its long axis, one at the centre, each
   * with its bites inside the wound. A suture grips, on each side of the
   * long axis, the skin's part of the wound's wall over @p bite_width mm
   * along the axis, through the dermis: each wall face's area share inside
   * that band, lumped onto its vertices (SutureAnchor weights). Throws,
   * naming Incision/Closure, where a bite grips no face (collective).
   */
  std::vector<Suture>
  find_sutures(const DisplacementField &field,
               const Incision          &incision,
               const double             spacing,
               const double             bite_width);

  /// A closed (or closing) wound: what the sutures carry and what the skin
  /// around them does.
  struct ClosureState
  {
    /// The closure fraction (1: the lips' ties drawn to zero length).
    double fraction = 0;
    /// The magnitude of each suture's force, N, by station.
    std::vector<double> suture_forces_N;
    std::vector<double> stations_mm;
    /// The largest distance between a suture's two bites, mm.
    double residual_gap_mm = 0;
    /// The largest von Mises stress of a skin cell (its mean), kPa, and
    /// where (reference x, y, mm).
    double                max_skin_stress_kPa = 0;
    std::array<double, 2> max_stress_at_mm    = {{0, 0}};
    /// The skin surface's largest rise during the closure (the dog ears at
    /// the wound's ends), mm, and where (reference x, y, mm).
    double                dog_ear_height_mm = 0;
    std::array<double, 2> dog_ear_at_mm     = {{0, 0}};

    double
    mean_force_N() const;

    double
    max_force_N() const;

    /// summary.json's entry of one closure.
    nlohmann::ordered_json
    to_json() const;
  };

  /**
   * Measures the closure by @p sutures of @p system's current solution at
   * fraction @p fraction; @p before is the (locally relevant) solution when
   * the closure started, from which the skin's rise is counted
   * (collective).
   */
  ClosureState
  measure_closure(const ElasticSystem                 &system,
                  const SutureTies                    &sutures,
                  const TrilinosWrappers::MPI::Vector &before,
                  const double                         fraction);
} // namespace ssc

#endif
