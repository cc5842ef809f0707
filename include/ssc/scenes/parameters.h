#ifndef ssc_scenes_parameters_h
#define ssc_scenes_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

#include <ssc/base/resource_limits.h>
#include <ssc/materials/layer_materials.h>
#include <ssc/mechanics/elasticity_parameters.h>
#include <ssc/mechanics/embedded_parameters.h>
#include <ssc/mesh/layer_stack.h>
#include <ssc/mesh/mesh_parameters.h>
#include <ssc/microstructure/microstructure_parameters.h>
#include <ssc/nonlinear/newton_parameters.h>
#include <ssc/scenes/growth_parameters.h>
#include <ssc/scenes/identification_parameters.h>
#include <ssc/scenes/incision_parameters.h>
#include <ssc/scenes/punch_parameters.h>
#include <ssc/scenes/run_parameters.h>
#include <ssc/scenes/time_parameters.h>

namespace ssc
{
  /**
   * Parses @p file into @p prm. A line 'include OTHER.prm' (outside any
   * subsection) parses OTHER.prm at that point, relative to the folder of
   * the file that includes it, so that region files (prm/regions/) can be
   * shared by the scene files of that region; later lines override.
   */
  void
  parse_with_includes(ParameterHandler  &prm,
                      const std::string &file,
                      const bool         skip_undefined,
                      const unsigned int depth,
                      unsigned int      &n_files);

  /// The same from the top: @p file at depth 0, at most 1000 files in all.
  inline void
  parse_with_includes(ParameterHandler  &prm,
                      const std::string &file,
                      const bool         skip_undefined)
  {
    unsigned int n_files = 0;
    parse_with_includes(prm, file, skip_undefined, 0, n_files);
  }

  /**
   * All parameters of one run, read from a prm file plus command-line
   * overrides "Section/Subsection/Name=value". Every entry is declared
   * once, bound to its member (ParameterHandler::add_parameter), whose
   * initial value is the default. Parsing takes two passes because the prm
   * file decides which layer sections exist: the first pass reads only the
   * layer list (tolerating everything else), the second declares one
   * section per layer and parses strictly. The handler keeps references to
   * the members, so a Parameters object is neither copied nor moved.
   */
  class Parameters
  {
  public:
    Parameters()                   = default;
    Parameters(const Parameters &) = delete;
    Parameters &
    operator=(const Parameters &) = delete;

    /// Reads @p file (if not empty) and applies @p overrides; throws
    /// ExcMessage naming the parameter (and file and line) on bad input.
    void
    read(const std::string &file, const std::vector<std::string> &overrides);

    /// Prints every parameter with default and documentation.
    static void
    print_defaults(std::ostream &out);

    /// Writes the parameters actually used, in prm format: running it
    /// again reproduces the run.
    void
    print_used(std::ostream &out) const;

    RunParameters run;
    LayerStack    layers;
    /// The parameters each law owns, per layer (Layer stack/<layer>/<law>).
    LayerLawParameters       materials;
    MeshParameters           mesh;
    ElasticityParameters     elasticity;
    PunchParameters          punch;
    GrowthParameters         growth;
    IncisionParameters       incision;
    TimeParameters           time;
    MicrostructureParameters microstructure;
    EmbeddedParameters       embedded;
    NewtonParameters         newton;
    ResourceLimits           limits;
    IdentificationParameters identification;

    /// The parameter file read (empty if none) and the overrides applied:
    /// a scene that runs variants of its own model (the identification's
    /// forward solves) reads them again with overrides of its own.
    const std::string &
    file() const
    {
      return parameter_file;
    }

    const std::vector<std::string> &
    overrides() const
    {
      return applied_overrides;
    }

  private:
    /// Declares every section, bound to the members, with one section per
    /// layer in @p layers.
    void
    add_parameters(ParameterHandler               &handler,
                   const std::vector<std::string> &layers);

    /// Checks each section and derives what follows from the values.
    void
    finalise();

    /// Cross-checks between sections: every inconsistent combination a run
    /// would reject.
    void
    check_consistency() const;

    /// The formulation, supports and contact options that need a
    /// finite-strain law or a particular mesh.
    void
    check_formulation(const LayerMaterials &layer_laws) const;

    /// Lobules, ligaments and growth against the layers and the patch.
    void
    check_microstructure() const;

    /// The punch inside the patch and the body (indentation).
    void
    check_punch_fits() const;

    /// The cut inside the patch, on its mesh lines, and a pre-tension to
    /// open it (incision).
    void
    check_incision(const LayerMaterials &layer_laws) const;

    /// What the identification's forward model needs.
    void
    check_identification(const LayerMaterials &layer_laws) const;

    ParameterHandler         prm;
    std::string              parameter_file;
    std::vector<std::string> applied_overrides;
  };
} // namespace ssc

#endif
