#ifndef ssc_parameters_h
#define ssc_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <ssc/background_mesh.h>
#include <ssc/layer_stack.h>
#include <ssc/mechanics/elasticity_parameters.h>
#include <ssc/mechanics/embedded_parameters.h>
#include <ssc/mechanics/newton_parameters.h>
#include <ssc/microstructure/microstructure_parameters.h>
#include <ssc/scenes/growth_parameters.h>
#include <ssc/scenes/punch_parameters.h>

#include <string>
#include <vector>

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
                      const unsigned int depth = 0);

  /// Section "Run": which scene, where its results go.
  struct RunParameters
  {
    std::string scene            = "indentation";
    std::string name             = "indentation";
    std::string output_directory = "output";
    bool        test_mode        = false;
    bool        write_fields     = true;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /**
   * All parameters of one run, read from a prm file plus command-line
   * overrides "Section/Subsection/Name=value". Parsing takes two passes
   * because the prm file decides which layer sections exist: the first
   * pass reads only the layer list (tolerating everything else), the
   * second declares one section per layer and parses strictly.
   */
  class Parameters
  {
  public:
    /// Reads @p file (if not empty) and applies @p overrides; throws
    /// ExcMessage naming the parameter (and file and line) on bad input.
    void
    read(const std::string &file, const std::vector<std::string> &overrides);

    /// Prints every parameter with default and documentation.
    static void
    print_defaults(std::ostream &out);

    /// Writes the parameters actually used, in prm format.
    void
    print_used(std::ostream &out) const;

    RunParameters            run;
    LayerStack               layers;
    MeshParameters           mesh;
    ElasticityParameters     elasticity;
    PunchParameters          punch;
    GrowthParameters         growth;
    MicrostructureParameters microstructure;
    EmbeddedParameters       embedded;
    NewtonParameters         newton;

  private:
    static void
    declare(ParameterHandler &prm, const std::vector<std::string> &layers);

    /// Cross-checks between sections (geometry consistency).
    void
    check_consistency() const;

    ParameterHandler prm;
  };
} // namespace ssc

#endif
