// Bad input never crashes: each case gives exit status 1 and one message
// that names the parameter (and file and line where the parser knows them).

#include <filesystem>
#include <fstream>
#include <sstream>

#include <ssc/application.h>

#include "tests.h"

namespace
{
  const char *valid_stack = R"(
subsection Layer stack
  set Layers = skin, fat
  subsection skin
    set Thickness = 1.5
  end
  subsection fat
    set Kind      = SAT
    set Thickness = 4
  end
end
)";

  void
  check(const std::string              &label,
        const std::string              &prm_text,
        const std::vector<std::string> &extra_arguments = {})
  {
    const std::string file = "case.prm";
    {
      std::ofstream out(file);
      out << prm_text;
    }
    std::vector<std::string> arguments = {file};
    arguments.insert(arguments.end(),
                     extra_arguments.begin(),
                     extra_arguments.end());
    std::ostringstream out, err;
    const int          status =
      ssc::run_command_line(arguments, MPI_COMM_WORLD, out, err);
    std::string message = err.str();
    // the file name is written by the test itself; keep only its base name
    const std::string full = std::filesystem::absolute(file).string();
    for (auto pos = message.find(full); pos != std::string::npos;
         pos      = message.find(full))
      message.replace(pos, full.size(), file);
    while (!message.empty() && message.back() == '\n')
      message.pop_back();
    // the memory this machine has is not part of the reference output
    const auto memory = message.find(" GB this run may use");
    if (memory != std::string::npos)
      {
        const auto start = message.rfind("of the ", memory) + 7;
        message.replace(start, memory - start, "<memory>");
      }
    dealii::deallog << label << ": exit status " << status << std::endl
                    << "  " << message << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  {
    std::ostringstream out, err;
    const int          status =
      ssc::run_command_line({"no/such/file.prm"}, MPI_COMM_WORLD, out, err);
    std::string message = err.str();
    message.pop_back(); // the final newline
    dealii::deallog << "missing file: exit status " << status << std::endl
                    << "  " << message << std::endl;
  }
  {
    std::filesystem::create_directories("a_folder.prm");
    std::ostringstream out, err;
    const int          status =
      ssc::run_command_line({"a_folder.prm"}, MPI_COMM_WORLD, out, err);
    std::string message = err.str();
    message.pop_back(); // the final newline
    dealii::deallog << "a folder as the parameter file: exit status " << status
                    << std::endl
                    << "  " << message << std::endl;
  }
  check("unknown parameter", "subsection Mesh\n  set Cell sise = 2\nend\n");
  check("unknown section", "subsection Meshes\n  set Cell size = 2\nend\n");
  check("malformed value", "subsection Mesh\n  set Cell size = two\nend\n");
  check("negative modulus",
        "subsection Layer stack\n  set Layers = skin\n  subsection skin\n"
        "    set Young's modulus = -0.02\n  end\nend\n");
  check("nu = 0.5",
        "subsection Layer stack\n  set Layers = skin\n  subsection skin\n"
        "    set Poisson's ratio = 0.5\n  end\nend\n");
  check("nu > 0.5",
        "subsection Layer stack\n  set Layers = skin\n  subsection skin\n"
        "    set Poisson's ratio = 0.7\n  end\nend\n");
  check("no layers", "subsection Layer stack\n  set Layers =\nend\n");
  check("a layer named other than a kind, without a Kind",
        "subsection Layer stack\n  set Layers = skin, fat\nend\n");
  check("duplicate layer",
        "subsection Layer stack\n  set Layers = fat, fat\nend\n");
  check("negative thickness",
        "subsection Layer stack\n  set Layers = skin\n  subsection skin\n"
        "    set Thickness = -1\n  end\nend\n");
  check("thickness negative at the patch edge",
        "subsection Layer stack\n  set Layers = skin\n  subsection skin\n"
        "    set Thickness = 1 + 0.1*x\n  end\nend\n");
  check("thickness not an expression",
        "subsection Layer stack\n  set Layers = skin\n  subsection skin\n"
        "    set Thickness = 1 + wobble\n  end\nend\n");
  check("punch wider than the patch",
        std::string(valid_stack) +
          "subsection Punch\n  set Radius = 25\nend\n");
  check("unknown -s parameter", valid_stack, {"-s", "Mesh/Cell sise=1"});
  check("-s value out of range", valid_stack, {"-s", "Elasticity/Degree=7"});
  check("-s without '='", valid_stack, {"-s", "Mesh/Cell size"});
  check("unknown option", valid_stack, {"--fast"});
  check("empty run name",
        std::string(valid_stack) + "subsection Run\n  set Name = \nend\n");

  const std::string geometry =
    "subsection Run\n  set Scene = geometry\nend\n"
    "subsection Layer stack\n  set Layers = skin, SAT, deep\n"
    "  subsection SAT\n    set Lobule diameter = 0\n  end\nend\n";
  check("lobules but no lobule diameter",
        geometry + "subsection Microstructure\n  set Lobules = true\nend\n");
  check(
    "region of interest outside the patch",
    geometry +
      "subsection Microstructure\n  subsection Ligaments\n    set Enabled = true\n  end\n"
      "  subsection Region of interest\n    set Shape = box\n"
      "    set Centre x = 100\n  end\nend\n");
  check(
    "ligament target missing",
    geometry +
      "subsection Microstructure\n  subsection Ligaments\n    set Enabled = true\n  end\n"
      "  subsection Ligaments\n    set Target = SM\n  end\n"
      "end\n");
  check(
    "negative ligament density",
    geometry +
      "subsection Microstructure\n  subsection Ligaments\n    set Enabled = true\n  end\n"
      "  subsection Ligaments\n    set Target = deep\n"
      "    set Density = 1 - 0.1*x\n  end\nend\n");
  check("tension-field septa with linear layers",
        std::string(valid_stack) +
          "subsection Embedded\n  subsection Septa\n"
          "    set Tension field = true\n  end\nend\n");
  check("edge contact with linear layers",
        std::string(valid_stack) +
          "subsection Punch\n  set Edge contact = true\nend\n");
  check("edge radius larger than the punch",
        std::string(valid_stack) +
          "subsection Layer stack\n  subsection fat\n"
          "    set Material model = neo-Hookean\n  end\nend\n"
          "subsection Punch\n  set Edge contact = true\n"
          "  set Radius = 2\n  set Edge radius = 3\nend\n");
  check("punch tied on its flat face without the edge contact",
        std::string(valid_stack) +
          "subsection Punch\n  set Tied region = flat face\nend\n");
  check("punch friction on linear elasticity",
        std::string(valid_stack) +
          "subsection Punch\n  set Contact = friction\nend\n");
  check("volumetric stabilisation without the mean dilatation",
        std::string(valid_stack) +
          "subsection Layer stack\n  subsection fat\n"
          "    set Material model = neo-Hookean\n  end\nend\n"
          "subsection Elasticity\n  set Volumetric stabilisation = 0.02\n"
          "end\n");
  check("acceptable forcing term below the largest one",
        std::string(valid_stack) +
          "subsection Nonlinear solver\n  set Max forcing term = 0.2\n"
          "  set Acceptable forcing term = 0.05\nend\n");
  check("unknown material model",
        std::string(valid_stack) +
          "subsection Layer stack\n  subsection fat\n"
          "    set Material model = Mooney-Rivlin\n  end\nend\n");
  check("volumetric energy where round 2 had it",
        std::string(valid_stack) +
          "subsection Layer stack\n  subsection fat\n"
          "    set Material model = neo-Hookean\n"
          "    set Volumetric energy = quadratic\n  end\nend\n");
  check("a law's parameter out of its range",
        std::string(valid_stack) +
          "subsection Layer stack\n  subsection fat\n"
          "    set Material model = neo-Hookean\n"
          "    subsection neo-Hookean\n"
          "      set Volumetric energy = cubic\n    end\n  end\nend\n");
  check("contact penalty that ruins the tangent",
        std::string(valid_stack) +
          "subsection Punch\n  set Contact penalty = 1e30\nend\n");
  check("friction penalty that ruins the tangent",
        std::string(valid_stack) +
          "subsection Punch\n  set Friction penalty = 1e30\nend\n");
  check("linear solver tolerance that stops CG before an answer",
        std::string(valid_stack) +
          "subsection Elasticity\n  subsection Linear solver\n"
          "    set Tolerance = 1\n  end\nend\n");
  const std::string growth = std::string(valid_stack) +
                             "subsection Run\n  set Scene = growth\n"
                             "  set Output directory = results\nend\n";
  check("growth of a layer that does not exist",
        growth + "subsection Growth\n  set Layers = muscle\nend\n");
  check("growth region that holds no material",
        growth + "subsection Growth\n  set Layers = fat\n"
                 "  set Region = ellipsoid\n  set Centre = 0, 0, 50\n"
                 "  set Semi-axes = 1, 1, 1\nend\n");
  check("growth ellipsoid with a zero semi-axis",
        growth + "subsection Growth\n  set Layers = fat\n"
                 "  set Region = ellipsoid\n  set Semi-axes = 1, 0, 1\n"
                 "end\n");
  check("growth centre with two coordinates",
        growth + "subsection Growth\n  set Layers = fat\n"
                 "  set Centre = 0, -2\nend\n");
  check("growth where no lobule may grow",
        growth + "subsection Growth\n  set Layers = fat\n"
                 "  set Growing lobule fraction = 0\nend\n");
  check("growth where the draws let no lobule grow",
        growth + "subsection Growth\n  set Layers = fat\n"
                 "  set Growing lobule fraction = 1e-6\nend\n"
                 "subsection Microstructure\n  set Lobules = true\nend\n");
  check("growth of a billion mm^3",
        growth + "subsection Growth\n  set Layers = fat\n"
                 "  set Added volume = 1e9\nend\n");
  check("contracted ligaments at small strain",
        std::string(valid_stack) +
          "subsection Embedded\n  subsection Ligaments\n"
          "    set Contraction = 0.1\n  end\nend\n");
  check("ligaments inclined beyond 75 degrees",
        std::string(valid_stack) +
          "subsection Microstructure\n  subsection Ligaments\n"
          "    set Enabled = true\n    set Inclination = 80\n  end\nend\n");
  check("fasciotomy with nothing to cut",
        std::string(valid_stack) +
          "subsection Microstructure\n  subsection Fasciotomy\n"
          "    set Enabled = true\n  end\nend\n");
  // values that are in their pattern's range but would break the model
  const auto fat = [](const std::string &entry) {
    return std::string(valid_stack) +
           "subsection Layer stack\n  subsection fat\n    set " + entry +
           "\n  end\nend\n";
  };
  check("punch deeper than the layer stack",
        std::string(valid_stack) + "subsection Punch\n  set Depth = 1e308\n"
                                   "end\n");
  check("thickness with rand()", fat("Thickness = 3 + rand()"));
  check("thickness infinite on a line", fat("Thickness = 1/abs(x)"));
  check("thickness of 1e-300 mm", fat("Thickness = 1e-300"));
  // a dip narrower than the parameter check's sample spacing, on a mesh
  // line (x = 2): the background mesh's vertex check finds it
  check("thickness negative only between the sample points",
        fat("Thickness = 1 - 2*exp(-10000*(x-2)^2)") +
          "subsection Run\n  set Output directory = results\nend\n"
          "subsection Mesh\n  set Patch length x = 41\n"
          "  set Cell size = 1\n  set Grading ratio = 1.2\nend\n");
  check("Poisson's ratio near -1", fat("Poisson's ratio = -0.9999999"));
  check("moduli a billion times apart",
        fat("Young's modulus = 1e-9") +
          "subsection Layer stack\n  subsection skin\n"
          "    set Young's modulus = 1\n  end\nend\n");
  check("run name with bytes that are not ASCII",
        std::string(valid_stack) + "subsection Run\n  set Name = a\xff\xfe" +
          "b\nend\n");
  check("punch between the surface nodes",
        std::string(valid_stack) +
          "subsection Run\n  set Output directory = results\nend\n"
          "subsection Mesh\n  set Patch length x = 4\n"
          "  set Patch length y = 4\n  set Cell size = 4\nend\n"
          "subsection Punch\n  set Radius = 1\nend\n");
  // models too large for the machine, refused before their cost is paid
  const std::string fat_lobules =
    std::string(valid_stack) +
    "subsection Microstructure\n  set Lobules = true\nend\n";
  check("lobules of 0.2 mm",
        fat_lobules,
        {"-s", "Layer stack/fat/Lobule diameter=0.2"});
  check("septum triangles of 1e-3 mm",
        fat_lobules,
        {"-s", "Microstructure/Septum triangle size=1e-3"});
  const std::string ligaments =
    "subsection Layer stack\n  set Layers = skin, SAT, deep\nend\n"
    "subsection Microstructure\n  subsection Ligaments\n"
    "    set Enabled = true\n    set Target = deep\n  end\nend\n";
  check("1e5 ligaments per cm^2",
        ligaments,
        {"-s", "Microstructure/Ligaments/Density=1e5"});
  check("ligament segments of 1e-6 mm",
        ligaments,
        {"-s", "Microstructure/Ligaments/Segment length=1e-6"});
  check("eight global refinements",
        valid_stack,
        {"-s", "Mesh/Global refinements=8"});
  check("o-grid without its circle", valid_stack, {"-s", "Mesh/Layout=o-grid"});
  check("o-grid with 30 cells around",
        valid_stack,
        {"-s",
         "Mesh/Layout=o-grid",
         "-s",
         "Mesh/Fitted circle radius=2.5",
         "-s",
         "Mesh/O-grid/Cells around=30"});
  check("o-grid on a circle with rollers",
        valid_stack,
        {"-s",
         "Mesh/Layout=o-grid",
         "-s",
         "Mesh/Fitted circle radius=2.5",
         "-s",
         "Mesh/O-grid/Outer boundary=circle"});
  const std::vector<std::string> probe = {"-s",
                                          "Punch/Shape=rectangle",
                                          "-s",
                                          "Punch/Length=45",
                                          "-s",
                                          "Punch/Width=8",
                                          "-s",
                                          "Mesh/Patch length x=80",
                                          "-s",
                                          "Run/Output directory=results"};
  check("a rectangular probe whose edges cut through cells",
        valid_stack,
        probe);
  std::vector<std::string> probe_on_o_grid = probe;
  probe_on_o_grid.insert(
    probe_on_o_grid.end(),
    {"-s", "Mesh/Layout=o-grid", "-s", "Mesh/Fitted circle radius=2"});
  check("a rectangular probe on an o-grid", valid_stack, probe_on_o_grid);
  std::vector<std::string> probe_edge_contact = probe;
  probe_edge_contact.insert(probe_edge_contact.end(),
                            {"-s", "Punch/Edge contact=true"});
  check("a rectangular probe with edge contact",
        valid_stack,
        probe_edge_contact);
  check("a quarter model with lobules",
        valid_stack,
        {"-s", "Mesh/Symmetry=quarter", "-s", "Microstructure/Lobules=true"});
  check("a quarter model of a thickness that is not symmetric",
        valid_stack,
        {"-s",
         "Mesh/Symmetry=quarter",
         "-s",
         "Layer stack/fat/Thickness=4 + 0.05*x"});
  check("a coarser-mesh depth error estimate without refinement levels",
        valid_stack,
        {"-s",
         "Punch/Control=force",
         "-s",
         "Punch/Depth error estimate=coarser mesh"});
  check("a depth error estimate under displacement control",
        valid_stack,
        {"-s",
         "Punch/Control=displacement",
         "-s",
         "Punch/Depth error estimate=enriched degree"});
  check("local refinements beyond the cell limit",
        std::string(valid_stack) +
          "subsection Run\n  set Output directory = results\nend\n"
          "subsection Mesh\n  subsection Region of interest\n"
          "    set Local refinements = 20\n  end\nend\n"
          "subsection Limits\n  set Max cells = 20000\nend\n");
  check(
    "a model larger than the memory allowed",
    valid_stack,
    {"-s", "Limits/Memory fraction=0.01", "-s", "Mesh/Global refinements=2"});
  check("a core edge cell size of 1e-9 mm",
        valid_stack,
        {"-s",
         "Mesh/Core edge cell size=1e-9",
         "-s",
         "Mesh/Grading ratio=1.1",
         "-s",
         "Run/Output directory=results"});
  check("an elevation grid of 1e-3 mm",
        growth + "subsection Growth\n  set Layers = fat\n"
                 "  set Grid spacing = 1e-3\nend\n");
  {
    // each file includes the next one four times: 4^14 parses
    for (unsigned int i = 1; i <= 15; ++i)
      {
        std::ofstream out("fan" + std::to_string(i) + ".prm");
        for (unsigned int k = 0; i < 15 && k < 4; ++k)
          out << "include fan" << i + 1 << ".prm\n";
      }
    check("an include fan-out", "include fan1.prm\n");
  }

  {
    // the identification: a valid set-up, then one fault at a time
    std::ifstream data(SOURCE_DIR "/data/multis_small.csv");
    std::string   header, row;
    std::getline(data, header);
    std::ofstream odd_probe("odd_probe.csv");
    odd_probe << header << '\n';
    for (unsigned int k = 0; k < 3 && std::getline(data, row); ++k)
      {
        // the last column, maxForce_normArea, gives the probe area: make it
        // 500 mm^2 (MaxForce is the tenth column)
        std::vector<std::string> fields;
        std::stringstream        line(row);
        for (std::string field; std::getline(line, field, ',');)
          fields.push_back(field);
        fields.back() = std::to_string(std::stod(fields[9]) / 500.);
        for (unsigned int i = 0; i < fields.size(); ++i)
          odd_probe << (i > 0 ? "," : "") << fields[i];
        odd_probe << '\n';
      }
    odd_probe.close();
    const std::string identification =
      "subsection Run\n  set Scene = identification\n"
      "  set Output directory = results\nend\n"
      "subsection Layer stack\n  set Layers = skin, fat, muscle\n"
      "  subsection skin\n    set Material model = linear\n  end\n"
      "  subsection fat\n    set Kind = SAT\n"
      "    set Material model = linear\n  end\n"
      "  subsection muscle\n    set Kind = deep\n"
      "    set Material model = linear\n  end\nend\n"
      "subsection Punch\n  set Shape = rectangle\n  set Length = 45\n"
      "  set Width = 8\n  set Control = force\nend\n";
    std::filesystem::copy_file(
      SOURCE_DIR "/data/multis_small.csv",
      "small.csv",
      std::filesystem::copy_options::overwrite_existing);
    const std::vector<std::string> with_data = {
      "-s", "Identification/Data file=small.csv"};
    const auto with = [&with_data](const std::string &setting) {
      std::vector<std::string> arguments = with_data;
      arguments.insert(arguments.end(), {"-s", setting});
      return arguments;
    };
    check("identification without a data file", identification);
    check("identification data file missing",
          identification,
          {"-s", "Identification/Data file=no_such.csv"});
    check("identification of a site not in the data",
          identification,
          with("Identification/Sites=XX_Y"));
    check("identification with all subjects in training",
          identification,
          with("Identification/Training fraction=1"));
    check("identification with fewer data than moduli",
          identification,
          with("Identification/Fitted data=stiffness"));
    check("identification of a finite-strain model",
          identification,
          with("Layer stack/fat/Material model=neo-Hookean"));
    std::string two_layers = identification;
    two_layers.replace(two_layers.find("skin, fat, muscle"), 17, "skin, fat");
    two_layers.erase(two_layers.find("  subsection muscle"),
                     two_layers.find("end\nsubsection Punch") -
                       two_layers.find("  subsection muscle"));
    check("identification of two layers", two_layers, with_data);
    check("identification of a circular punch",
          identification,
          with("Punch/Shape=circle"));
    check("identification of one site twice",
          identification,
          with("Identification/Sites=LA_A, LA_A"));
    check("identification with a negative split seed",
          identification,
          with("Identification/Split seed=-1"));
    check("identification with a patch a million tissue thicknesses wide",
          identification,
          with("Identification/Patch margin=1e6"));
    check("identification with an unknown probe face",
          identification,
          {"-s",
           "Identification/Data file=odd_probe.csv",
           "-s",
           "Identification/Sites=LA_A"});
    // --check reads the data file and checks every site as a run would
    // before its first fit
    check("--check: identification data file missing",
          identification,
          {"-s", "Identification/Data file=no_such.csv", "--check"});
    std::ofstream("garbage.csv") << "hello\nworld\n";
    check("--check: identification data file that is not a table",
          identification,
          {"-s", "Identification/Data file=garbage.csv", "--check"});
    std::ifstream small(SOURCE_DIR "/data/multis_small.csv");
    std::getline(small, header);
    std::getline(small, row);
    std::ofstream("one_subject.csv") << header << '\n' << row << '\n';
    check("--check: identification site with one subject",
          identification,
          {"-s",
           "Identification/Data file=one_subject.csv",
           "-s",
           "Identification/Sites=LA_A",
           "--check"});
  }

  check("missing include", "include no_such_region.prm\n");
  check("include inside a subsection",
        "subsection Mesh\n  include other.prm\nend\n");
}
