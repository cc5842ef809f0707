#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <deal.II/grid/reference_cell.h>

#include <fstream>

#include <ssc/base/empty_vtu.h>
#include <ssc/output/embedded_output.h>

namespace ssc
{
  template <int dim>
  EmbeddedFieldWriter<dim>::EmbeddedFieldWriter(
    const Triangulation<dim, 3> &mesh,
    const PointLocator          &locator)
    : mesh(mesh)
    , communicator(locator.communicator())
  {
    std::vector<Point<3>> points;
    for (const auto &cell : mesh.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        points.push_back(cell->vertex(v));
    for (const auto &cell : mesh.active_cell_iterators())
      {
        points.push_back(cell->center());
        Tensor<1, 3> d;
        if (dim == 1)
          d = cell->vertex(1) - cell->vertex(0);
        else
          d = cross_product_3d(cell->vertex(1) - cell->vertex(0),
                               cell->vertex(2) - cell->vertex(0));
        directions.push_back(d.norm() > 0 ? d / d.norm() : d);
      }
    locations = locator.locate(points);
  }


  template <int dim>
  void
  EmbeddedFieldWriter<dim>::write(const RunOutput              &output,
                                  const std::string            &file,
                                  const DisplacementField      &field,
                                  const std::vector<CellField> &fields) const
  {
    std::vector<Tensor<1, 3>> u;
    std::vector<Tensor<2, 3>> gradient;
    field.evaluate_at(locations, u, gradient);
    std::vector<DataOutBase::Patch<dim, 3>> patches;
    std::vector<std::string>                names;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      fill_patches(u, gradient, fields, patches, names);
    output.write_file(file, [&](std::ostream &out) {
      const std::vector<
        std::tuple<unsigned int,
                   unsigned int,
                   std::string,
                   DataComponentInterpretation::DataComponentInterpretation>>
                            vectors = {{0,
                                        2,
                                        "displacement",
                                        DataComponentInterpretation::component_is_part_of_vector}};
      DataOutBase::VtkFlags flags;
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      if (patches.empty())
        write_empty_vtu(out);
      else
        DataOutBase::write_vtu(patches, names, vectors, flags, out);
    });
  }


  template <int dim>
  void
  EmbeddedFieldWriter<dim>::fill_patches(
    const std::vector<Tensor<1, 3>>         &u,
    const std::vector<Tensor<2, 3>>         &gradient,
    const std::vector<CellField>            &fields,
    std::vector<DataOutBase::Patch<dim, 3>> &patches,
    std::vector<std::string>                &names) const
  {
    const ReferenceCell reference_cell =
      dim == 1 ? ReferenceCells::Line : ReferenceCells::Triangle;
    const unsigned int n_vertices = dim + 1;
    unsigned int       vertex = 0, c = 0;
    const unsigned int first_centre = mesh.n_active_cells() * n_vertices;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        DataOutBase::Patch<dim, 3> patch;
        patch.reference_cell = reference_cell;
        patch.n_subdivisions = 1;
        patch.data.reinit(3 + fields.size(), n_vertices);
        const Tensor<2, 3> F =
          unit_symmetric_tensor<3>() + gradient[first_centre + c];
        for (unsigned int v = 0; v < n_vertices; ++v, ++vertex)
          {
            patch.vertices[v] = cell->vertex(v);
            for (unsigned int d = 0; d < 3; ++d)
              patch.data(d, v) = u[vertex][d];
          }
        for (unsigned int f = 0; f < fields.size(); ++f)
          {
            const double value =
              fields[f].second(F, directions[c], cell->material_id());
            for (unsigned int v = 0; v < n_vertices; ++v)
              patch.data(3 + f, v) = value;
          }
        patch.patch_index = c++;
        patches.push_back(patch);
      }

    names = {"displacement", "displacement", "displacement"};
    for (const auto &field : fields)
      names.push_back(field.first);
  }


  template class EmbeddedFieldWriter<1>;
  template class EmbeddedFieldWriter<2>;
} // namespace ssc
