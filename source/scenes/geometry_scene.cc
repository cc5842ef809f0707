#include <deal.II/lac/vector.h>

#include <deal.II/numerics/data_out.h>

#include <fstream>
#include <iomanip>
#include <sstream>

#include <ssc/mesh/background_mesh.h>
#include <ssc/microstructure/microstructure.h>
#include <ssc/scenes/geometry_scene.h>
#include <ssc/scenes/scene_run.h>

namespace ssc
{
  namespace
  {
    /// The background mesh with its layer index per cell (VTU + PVTU).
    std::string
    write_layer_ids(const BackgroundMesh &mesh, const RunOutput &output)
    {
      const auto   &tria = mesh.triangulation();
      Vector<float> layer(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          layer[cell->active_cell_index()] = cell->material_id();
      DataOut<3> data_out;
      data_out.attach_triangulation(tria);
      data_out.add_data_vector(layer, "layer", DataOut<3>::type_cell_data);
      data_out.build_patches();
      return output.write_vtu(data_out, "volume", 0);
    }
  } // namespace


  void
  GeometryScene::run()
  {
    SceneRun            scene(parameters, mpi_communicator, "geometry");
    ConditionalOStream &pcout  = scene.pcout();
    TimerOutput        &timer  = scene.timer();
    RunOutput          &output = scene.output();

    BackgroundMesh mesh(parameters.layers, parameters.mesh, mpi_communicator);
    {
      TimerOutput::Scope t(timer, "mesh");
      mesh.build();
    }
    pcout << "Mesh: " << mesh.triangulation().n_global_active_cells()
          << " hexahedra over " << parameters.layers.n_layers() << " layers"
          << std::endl;

    Microstructure microstructure(parameters.layers,
                                  parameters.mesh.patch_length_x,
                                  parameters.mesh.patch_length_y,
                                  parameters.microstructure);
    {
      TimerOutput::Scope t(timer, "microstructure");
      microstructure.build(
        [&pcout](const std::string &line) { pcout << line << std::endl; });
    }
    const nlohmann::ordered_json statistics = microstructure.statistics();
    for (const auto &layer : statistics["layers"])
      pcout << "Layer '" << layer["layer"].get<std::string>()
            << "': " << layer["lobules"] << " lobules, " << std::setprecision(4)
            << layer["mean_faces_per_lobule"].get<double>()
            << " faces per lobule, " << layer["septa"] << " septa, "
            << layer["septa_area_per_volume_per_mm"].get<double>()
            << " mm^2 of septa per mm^3" << std::endl;
    pcout << "Septa mesh: " << microstructure.septa_mesh().n_active_cells()
          << " triangles; ligaments: " << microstructure.ligaments().size()
          << " (" << microstructure.ligament_mesh().n_active_cells()
          << " segments)" << std::endl;

    {
      TimerOutput::Scope t(timer, "output");
      std::ostringstream csv;
      microstructure.write_lobules_csv(csv);
      output.write_text("lobules.csv", csv.str());
      output.write_file("septa.vtu", [&](std::ostream &out) {
        microstructure.write_septa_vtu(out);
      });
      output.write_file("ligaments.vtu", [&](std::ostream &out) {
        microstructure.write_ligaments_vtu(out);
      });
      output.add_pvd_record("volume", 0, write_layer_ids(mesh, output));
    }

    nlohmann::ordered_json summary =
      scene.summary(0, mesh.triangulation().n_global_active_cells());
    summary["embedded"] = {
      {"septa_triangles", microstructure.septa_mesh().n_active_cells()},
      {"ligament_segments", microstructure.ligament_mesh().n_active_cells()},
      {"lobules", microstructure.n_lobules()}};
    nlohmann::ordered_json per_layer, mean_faces, septa_density;
    double                 faces = 0;
    for (const auto &layer : statistics["layers"])
      {
        const std::string name = layer["layer"];
        per_layer[name]        = layer["lobules"];
        mean_faces[name]       = layer["mean_faces_per_lobule"];
        septa_density[name]    = layer["septa_area_per_volume_per_mm"];
        faces += layer["mean_faces_per_lobule"].get<double>() *
                 layer["lobules"].get<double>();
      }
    summary["lobules_per_layer"] = per_layer;
    summary["mean_faces_per_lobule"] =
      microstructure.n_lobules() > 0 ? faces / microstructure.n_lobules() : 0.;
    summary["mean_faces_per_lobule_per_layer"] = mean_faces;
    summary["septa_area_per_volume_per_layer"] = septa_density;
    summary["ligament_count"] = microstructure.ligaments().size();
    summary["microstructure"] = statistics;
    output.write_summary(summary);
    scene.print_wall_times();
  }
} // namespace ssc
