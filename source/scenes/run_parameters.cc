#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ssc/scenes/run_parameters.h>

namespace ssc
{
  void
  RunParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Run");
    prm.add_parameter("Scene",
                      scene,
                      "What to simulate. indentation: a rigid flat "
                      "cylindrical punch at the patch centre, pressed to "
                      "prescribed depths or with prescribed forces (section "
                      "Punch), with the microstructure embedded when it is "
                      "switched on. growth: fat lobules grow by a given "
                      "volume (section Growth: cellulite, fat injection), "
                      "the skin elevation is measured. geometry: build the "
                      "layered patch and its microstructure (lobules, septa, "
                      "ligaments) and write them, without mechanics. "
                      "identification: fit layer moduli to in vivo "
                      "indentations (section Identification). incision: "
                      "cut the pre-tensioned skin (section Incision) along "
                      "x and along y, and measure the wounds that open.");
    prm.add_parameter("Name",
                      name,
                      "Name of the run: results go to <Output directory>/"
                      "<Name>/.",
                      Patterns::Anything());
    prm.add_parameter("Output directory",
                      output_directory,
                      "Folder that holds one subfolder per run; relative "
                      "paths are taken from the current working directory.",
                      Patterns::Anything());
    prm.add_parameter("Write fields",
                      write_fields,
                      "Write the VTU/PVD field files (volume, septa, "
                      "ligaments); false keeps only the tables and "
                      "summary.json (benchmarks).");
    prm.add_parameter("Test mode",
                      test_mode,
                      "Print only what is deterministic (no timings, no "
                      "iteration counts), for reference-output tests.");
    prm.leave_subsection();
  }


  void
  RunParameters::check() const
  {
    const std::string trimmed = Utilities::trim(name);
    AssertThrow(!trimmed.empty() && trimmed == name &&
                  name.find('/') == std::string::npos && name != "." &&
                  name != "..",
                ExcMessage("Run/Name = '" + name +
                           "' must be a plain folder name (not empty, no "
                           "'/', no surrounding spaces)."));
    // the name goes into summary.json (UTF-8) and into a path
    for (const char c : name)
      AssertThrow(c >= 0x20 && c < 0x7f,
                  ExcMessage("Run/Name must consist of printable ASCII "
                             "characters (letters, digits, '_', '-', '.'): "
                             "it names the run's folder and goes into "
                             "summary.json."));
    AssertThrow(!Utilities::trim(output_directory).empty(),
                ExcMessage("Run/Output directory must not be empty."));
  }
} // namespace ssc
