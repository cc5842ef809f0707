#ifndef ssc_microstructure_microstructure_h
#define ssc_microstructure_microstructure_h

#include <deal.II/grid/tria.h>

#include <nlohmann/json.hpp>

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include <ssc/mesh/layer_stack.h>
#include <ssc/microstructure/ligaments.h>
#include <ssc/microstructure/lobules.h>
#include <ssc/microstructure/microstructure_parameters.h>

namespace ssc
{
  /// Anatomical tag of a septum: retinacula cutis superficialis (in SAT) or
  /// profundus (in DAT).
  enum class SeptumTag
  {
    RCS,
    RCP
  };

  /**
   * The procedural microstructure of the patch (docs/architecture.md §9): the
   * lobules of every adipose layer with their septa, the skin ligaments, and
   * the embedded meshes built from them — the septa as a Triangulation<2,3> of
   * triangles (material_id = index of the septum) and the ligaments as a
   * Triangulation<1,3> of segments (material_id = index of the ligament).
   * Deterministic from the seed, so every MPI rank builds the same one.
   */
  class Microstructure
  {
  public:
    Microstructure(const LayerStack               &layers,
                   const double                    patch_length_x,
                   const double                    patch_length_y,
                   const MicrostructureParameters &parameters);

    /// Builds what the parameters switch on; @p progress receives one line
    /// per phase, @p timed_progress the iterations of a long Lloyd
    /// relaxation.
    void
    build(const std::function<void(const std::string &)> &progress       = {},
          const std::function<void(const std::string &)> &timed_progress = {});

    /// Lobules and septa per adipose layer (only layers that carry lobules).
    const std::vector<LayerLobules> &
    lobule_layers() const
    {
      return layer_lobules;
    }

    /// All septa; the index is the material_id of their triangles.
    const std::vector<Septum> &
    septa() const
    {
      return all_septa;
    }

    SeptumTag
    tag(const Septum &septum) const;

    const std::vector<Ligament> &
    ligaments() const
    {
      return all_ligaments;
    }

    const Triangulation<2, 3> &
    septa_mesh() const
    {
      return septa_triangulation;
    }

    const Triangulation<1, 3> &
    ligament_mesh() const
    {
      return ligament_triangulation;
    }

    unsigned int
    n_lobules() const;

    /// id, layer, centroid x y z, volume_mm3, n_faces.
    void
    write_lobules_csv(std::ostream &out) const;

    /// The septa with their septum index, layer, tag (0 RCS, 1 RCP) and the
    /// ids of the two lobules as cell data.
    void
    write_septa_vtu(std::ostream &out) const;

    /// The ligaments with their index as cell data.
    void
    write_ligaments_vtu(std::ostream &out) const;

    /// Counts, mean faces per lobule, septa area per unit volume per layer,
    /// cleaning diagnostics and CVT energies, for summary.json.
    nlohmann::ordered_json
    statistics() const;

    /// What the fasciotomy cut (septa, their area, ligaments) and where,
    /// for summary.json.
    nlohmann::ordered_json
    fasciotomy_summary() const;

    /// Area-weighted centroid of a septum.
    static Point<3>
    centroid(const Septum &septum);

  private:
    /// Removes the septa and ligaments inside the fasciotomy.
    void
    cut_fasciotomy();

    void
    create_septa_mesh();

    void
    create_ligament_mesh();

    const LayerStack               &layers;
    const MicrostructureParameters &parameters;
    const BoundingBox<2>            rectangle;

    std::vector<LayerLobules> layer_lobules;
    std::vector<Septum>       all_septa;
    std::vector<Ligament>     all_ligaments;
    /// What the fasciotomy cut: septa, their area (mm^2), ligaments.
    unsigned int        n_cut_septa = 0, n_cut_ligaments = 0;
    double              cut_septa_area = 0;
    Triangulation<2, 3> septa_triangulation;
    Triangulation<1, 3> ligament_triangulation;
  };
} // namespace ssc

#endif
