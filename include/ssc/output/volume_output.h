#ifndef ssc_output_volume_output_h
#define ssc_output_volume_output_h

#include <deal.II/base/symmetric_tensor.h>

#include <string>
#include <vector>

#include <ssc/materials/layer_materials.h>
#include <ssc/materials/quadrature_history.h>
#include <ssc/mechanics/displacement_field.h>
#include <ssc/mechanics/growth_field.h>
#include <ssc/output/run_output.h>

namespace ssc
{
  /**
   * The Cauchy stress of every locally owned cell (indexed by active cell
   * index; zero elsewhere) from the cell's own law: its mean over the
   * deformed cell, from the law at the quadrature points (small strain for
   * linear layers, finite strain otherwise, with the growth of @p growth);
   * the laws with history (visco-elastic layers) in the last accepted state
   * of @p history; NaN in inverted cells. write_volume_vtu() writes these.
   */
  std::vector<SymmetricTensor<2, 3>>
  cell_cauchy_stresses(const DisplacementField &field,
                       const LayerMaterials    &materials,
                       const GrowthField       &growth,
                       const QuadratureHistory &history);

  /**
   * Writes the volume as VTU pieces (one per rank) with a PVTU record,
   * volume_<step>, into the run folder of @p output: the displacement, per
   * cell the Cauchy stress of cell_cauchy_stresses(), its von Mises
   * stress, the layer and the rank. Returns the name of the record
   * (collective).
   */
  std::string
  write_volume_vtu(const DisplacementField &field,
                   const LayerMaterials    &materials,
                   const GrowthField       &growth,
                   const QuadratureHistory &history,
                   const RunOutput         &output,
                   const unsigned int       step);
} // namespace ssc

#endif
