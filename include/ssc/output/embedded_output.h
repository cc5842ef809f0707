#ifndef ssc_output_embedded_output_h
#define ssc_output_embedded_output_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <ssc/embedding/point_locator.h>
#include <ssc/mechanics/displacement_field.h>
#include <ssc/output/run_output.h>

namespace ssc
{
  /**
   * Writes an embedded mesh (septa: triangles, ligaments: segments) with the
   * background displacement interpolated at its vertices and scalar fields
   * per cell computed from the background deformation gradient at the
   * cell's centre, as one VTU file written by rank 0. The vertices and
   * centres are located once, at construction.
   */
  template <int dim>
  class EmbeddedFieldWriter
  {
  public:
    /// A named scalar per embedded cell from the deformation gradient F
    /// at its centre, the cell's unit normal (membrane) or tangent (cable)
    /// and its material id.
    using CellField = std::pair<std::string,
                                std::function<double(const Tensor<2, 3> &,
                                                     const Tensor<1, 3> &,
                                                     types::material_id)>>;

    EmbeddedFieldWriter(const Triangulation<dim, 3> &mesh,
                        const PointLocator          &locator);

    /// Writes @p file into the run folder of @p output (rank 0;
    /// collective).
    void
    write(const RunOutput              &output,
          const std::string            &file,
          const DisplacementField      &field,
          const std::vector<CellField> &fields) const;

  private:
    /// The patches (one per embedded cell) and field names of the values
    /// @p u, @p gradient at locations.
    void
    fill_patches(const std::vector<Tensor<1, 3>>         &u,
                 const std::vector<Tensor<2, 3>>         &gradient,
                 const std::vector<CellField>            &fields,
                 std::vector<DataOutBase::Patch<dim, 3>> &patches,
                 std::vector<std::string>                &names) const;

    const Triangulation<dim, 3> &mesh;
    MPI_Comm                     communicator;
    /// Vertices of each cell in turn, then the cell centres.
    std::vector<PointLocation> locations;
    std::vector<Tensor<1, 3>>  directions;
  };
} // namespace ssc

#endif
