#include <deal.II/base/exceptions.h>

#include <deal.II/grid/tria_description.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <ssc/base/empty_vtu.h>
#include <ssc/microstructure/microstructure.h>

namespace ssc
{
  Microstructure::Microstructure(const LayerStack               &layers,
                                 const double                    patch_length_x,
                                 const double                    patch_length_y,
                                 const MicrostructureParameters &parameters)
    : layers(layers)
    , parameters(parameters)
    , rectangle(
        parameters.region.realisation_rectangle(patch_length_x, patch_length_y))
  {}


  void
  Microstructure::build(
    const std::function<void(const std::string &)> &progress,
    const std::function<void(const std::string &)> &timed_progress)
  {
    layer_lobules.clear();
    all_septa.clear();
    all_ligaments.clear();
    if (parameters.lobules)
      {
        unsigned int next_id = 0;
        for (unsigned int l = 0; l < layers.n_layers(); ++l)
          if (layers.layer(l).is_adipose() &&
              layers.layer(l).lobule_diameter > 0)
            {
              layer_lobules.push_back(build_layer_lobules(layers,
                                                          l,
                                                          rectangle,
                                                          parameters,
                                                          next_id,
                                                          progress,
                                                          timed_progress));
              next_id += layer_lobules.back().lobules.size();
              for (const auto &septum : layer_lobules.back().septa)
                all_septa.push_back(septum);
            }
        AssertThrow(!layer_lobules.empty(),
                    ExcMessage("Microstructure/Lobules is on, but no layer "
                               "of kind SAT or DAT has a positive Lobule "
                               "diameter."));
      }
    if (parameters.ligaments)
      {
        all_ligaments = place_ligaments(layers, rectangle, parameters);
        if (progress)
          progress("Skin ligaments: " + std::to_string(all_ligaments.size()));
      }
    cut_fasciotomy();
    if (progress && parameters.fasciotomy.enabled)
      {
        std::ostringstream line;
        line << "Fasciotomy: cut " << n_cut_septa << " septa ("
             << cut_septa_area << " mm^2) and " << n_cut_ligaments
             << " ligaments within " << parameters.fasciotomy.radius
             << " mm of (" << parameters.fasciotomy.centre << ")";
        progress(line.str());
      }
    create_septa_mesh();
    create_ligament_mesh();
  }


  Point<3>
  Microstructure::centroid(const Septum &septum)
  {
    Point<3> sum;
    double   area = 0;
    for (const auto &t : septum.triangles)
      {
        const double a =
          0.5 * cross_product_3d(t[1] - t[0], t[2] - t[0]).norm();
        sum += a / 3. * (t[0] + t[1] + t[2]);
        area += a;
      }
    return area > 0 ? Point<3>(sum / area) : septum.triangles.front()[0];
  }


  void
  Microstructure::cut_fasciotomy()
  {
    n_cut_septa = n_cut_ligaments = 0;
    cut_septa_area                = 0;
    const Fasciotomy &release     = parameters.fasciotomy;
    if (!release.enabled)
      return;
    const auto inside = [&release](const Septum &septum) {
      const Point<3> c = centroid(septum);
      return release.cuts(c[0], c[1]);
    };
    for (const Septum &septum : all_septa)
      if (inside(septum))
        {
          ++n_cut_septa;
          cut_septa_area += septum.area;
        }
    const auto erase_if = [](auto &container, const auto &predicate) {
      container.erase(std::remove_if(container.begin(),
                                     container.end(),
                                     predicate),
                      container.end());
    };
    erase_if(all_septa, inside);
    for (auto &layer : layer_lobules)
      erase_if(layer.septa, inside);
    const std::size_t before = all_ligaments.size();
    erase_if(all_ligaments, [&release](const Ligament &ligament) {
      return release.cuts(ligament.top[0], ligament.top[1]);
    });
    n_cut_ligaments = before - all_ligaments.size();
  }


  SeptumTag
  Microstructure::tag(const Septum &septum) const
  {
    return layers.layer(septum.layer).kind == LayerKind::SAT ? SeptumTag::RCS :
                                                               SeptumTag::RCP;
  }


  unsigned int
  Microstructure::n_lobules() const
  {
    unsigned int n = 0;
    for (const auto &l : layer_lobules)
      n += l.lobules.size();
    return n;
  }


  void
  Microstructure::create_septa_mesh()
  {
    septa_triangulation.clear();
    std::vector<Point<3>>    vertices;
    std::vector<CellData<2>> cells;
    for (unsigned int s = 0; s < all_septa.size(); ++s)
      for (const auto &triangle : all_septa[s].triangles)
        {
          CellData<2> cell(3);
          for (unsigned int v = 0; v < 3; ++v)
            {
              cell.vertices[v] = vertices.size();
              vertices.push_back(triangle[v]);
            }
          cell.material_id = s;
          cells.push_back(cell);
        }
    if (!cells.empty())
      septa_triangulation.create_triangulation(vertices, cells, SubCellData());
  }


  void
  Microstructure::create_ligament_mesh()
  {
    ligament_triangulation.clear();
    std::vector<Point<3>>    vertices;
    std::vector<CellData<1>> cells;
    for (unsigned int k = 0; k < all_ligaments.size(); ++k)
      {
        const Ligament    &ligament = all_ligaments[k];
        const double       length   = ligament.top.distance(ligament.bottom);
        const unsigned int n        = std::max(
          1., std::ceil(length / parameters.ligament_segment_length - 1e-12));
        const unsigned int first = vertices.size();
        for (unsigned int i = 0; i <= n; ++i)
          vertices.push_back(ligament.top + (double(i) / n) *
                                              (ligament.bottom - ligament.top));
        for (unsigned int i = 0; i < n; ++i)
          {
            CellData<1> cell;
            cell.vertices    = {first + i, first + i + 1};
            cell.material_id = k;
            cells.push_back(cell);
          }
      }
    if (!cells.empty())
      ligament_triangulation.create_triangulation(vertices,
                                                  cells,
                                                  SubCellData());
  }


  void
  Microstructure::write_lobules_csv(std::ostream &out) const
  {
    out << "id,layer,centroid_x,centroid_y,centroid_z,volume_mm3,n_faces\n"
        << std::setprecision(12);
    for (const auto &layer : layer_lobules)
      for (const auto &lobule : layer.lobules)
        out << lobule.id << ',' << layers.layer(lobule.layer).name << ','
            << lobule.centroid[0] << ',' << lobule.centroid[1] << ','
            << lobule.centroid[2] << ',' << lobule.volume << ','
            << lobule.n_faces << '\n';
  }


  namespace
  {
    template <int dim>
    void
    write_cell_data_vtu(
      const Triangulation<dim, 3> &tria,
      const std::vector<
        std::pair<std::string, std::function<double(types::material_id)>>>
                   &fields,
      std::ostream &out)
    {
      if (tria.n_active_cells() == 0)
        {
          write_empty_vtu(out); // DataOut cannot handle an empty mesh
          return;
        }
      DataOut<dim, 3> data_out;
      data_out.attach_triangulation(tria);
      std::vector<Vector<double>> data(fields.size(),
                                       Vector<double>(tria.n_active_cells()));
      for (const auto &cell : tria.active_cell_iterators())
        for (unsigned int f = 0; f < fields.size(); ++f)
          data[f][cell->active_cell_index()] =
            fields[f].second(cell->material_id());
      for (unsigned int f = 0; f < fields.size(); ++f)
        data_out.add_data_vector(data[f],
                                 fields[f].first,
                                 DataOut<dim, 3>::type_cell_data);
      data_out.build_patches();
      data_out.write_vtu(out);
    }
  } // namespace


  void
  Microstructure::write_septa_vtu(std::ostream &out) const
  {
    const auto septum = [this](const types::material_id id) -> const Septum & {
      return all_septa[id];
    };
    write_cell_data_vtu<2>(
      septa_triangulation,
      {{"septum", [](const types::material_id id) { return double(id); }},
       {"layer",
        [&](const types::material_id id) { return double(septum(id).layer); }},
       {"tag_RCS0_RCP1",
        [&](const types::material_id id) {
          return tag(septum(id)) == SeptumTag::RCS ? 0. : 1.;
        }},
       {"lobule_a",
        [&](const types::material_id id) {
          return double(septum(id).lobules[0]);
        }},
       {"lobule_b",
        [&](const types::material_id id) {
          return double(septum(id).lobules[1]);
        }}},
      out);
  }


  void
  Microstructure::write_ligaments_vtu(std::ostream &out) const
  {
    write_cell_data_vtu<1>(
      ligament_triangulation,
      {{"ligament", [](const types::material_id id) { return double(id); }}},
      out);
  }


  nlohmann::ordered_json
  Microstructure::statistics() const
  {
    nlohmann::ordered_json layers_json = nlohmann::ordered_json::array();
    for (const auto &l : layer_lobules)
      {
        double faces = 0, volume = 0, area = 0;
        for (const auto &lobule : l.lobules)
          {
            faces += lobule.n_faces;
            volume += lobule.volume;
          }
        for (const auto &septum : l.septa)
          area += septum.area;
        const unsigned int n = l.lobules.size();
        layers_json.push_back(
          {{"layer", layers.layer(l.layer).name},
           {"kind", to_string(layers.layer(l.layer).kind)},
           {"lobules", n},
           {"lobule_diameter_mm", layers.layer(l.layer).lobule_diameter},
           {"mean_faces_per_lobule", n > 0 ? faces / n : 0.},
           {"lobule_volume_mm3", volume},
           {"region_volume_mm3", l.region_volume},
           {"septa", l.septa.size()},
           {"septa_area_mm2", area},
           {"septa_area_per_volume_per_mm", volume > 0 ? area / volume : 0.},
           {"dropped_septa", l.n_dropped_septa},
           {"dropped_septa_area_mm2", l.dropped_septa_area},
           {"degenerate_faces", l.diagnostics.n_degenerate_faces},
           {"merged_vertices", l.diagnostics.n_merged_vertices},
           {"seeds_moved_inside", l.diagnostics.n_seeds_moved_inside},
           {"cvt_energy_initial", l.cvt_energy.front()},
           {"cvt_energy_final", l.cvt_energy.back()},
           {"wall_time_s", l.wall_time}});
      }
    unsigned int n_segments = ligament_triangulation.n_active_cells();
    return {{"lobules", n_lobules()},
            {"septa", all_septa.size()},
            {"septa_triangles", septa_triangulation.n_active_cells()},
            {"ligaments", all_ligaments.size()},
            {"ligament_segments", n_segments},
            {"layers", layers_json},
            {"fasciotomy", fasciotomy_summary()}};
  }


  nlohmann::ordered_json
  Microstructure::fasciotomy_summary() const
  {
    return {{"enabled", parameters.fasciotomy.enabled},
            {"centre_mm",
             {parameters.fasciotomy.centre[0],
              parameters.fasciotomy.centre[1]}},
            {"radius_mm", parameters.fasciotomy.radius},
            {"cut_septa", n_cut_septa},
            {"cut_septa_area_mm2", cut_septa_area},
            {"cut_ligaments", n_cut_ligaments}};
  }
} // namespace ssc
