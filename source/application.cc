#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <sstream>

#include <ssc/application.h>
#include <ssc/parameters.h>
#include <ssc/scenes/geometry_scene.h>
#include <ssc/scenes/growth_scene.h>
#include <ssc/scenes/indentation_scene.h>

namespace ssc
{
  namespace
  {
    const char *usage =
      "Usage: ssc FILE.prm [-s \"Section/Subsection/Name=value\"]...\n"
      "       ssc --check FILE.prm [-s ...]   parse and validate only\n"
      "       ssc --print-parameters          all parameters with defaults\n"
      "       ssc --help\n"
      "\n"
      "Runs the scene described by FILE.prm (units: mm, N, MPa, s; z out of\n"
      "the body, skin at z = 0) and writes output/<Run/Name>/: summary.json,\n"
      "parameters.prm, CSV tables, VTU/PVD fields and log.txt.\n"
      "-s overrides one parameter and may repeat, e.g.\n"
      "  ssc prm/punch.prm -s \"Mesh/Global refinements=1\"\n";

    /// The "additional information" of a deal.II exception, without the
    /// source location that is meaningless to a user.
    std::string
    user_message(const ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      std::string text = Utilities::trim(info.str());
      // collapse deal.II's indented multi-line layout into one paragraph
      std::string collapsed;
      bool        space = false;
      for (const char c : text)
        if (c == '\n' || c == ' ' || c == '\t')
          space = true;
        else
          {
            if (space && !collapsed.empty())
              collapsed += ' ';
            collapsed += c;
            space = false;
          }
      return collapsed;
    }
  } // namespace


  int
  run_command_line(const std::vector<std::string> &arguments,
                   const MPI_Comm                  mpi_communicator,
                   std::ostream                   &out,
                   std::ostream                   &err)
  {
    const bool  root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    std::string file;
    std::vector<std::string> overrides;
    bool                     check_only = false;
    try
      {
        for (unsigned int i = 0; i < arguments.size(); ++i)
          {
            const std::string &arg = arguments[i];
            if (arg == "-h" || arg == "--help")
              {
                if (root)
                  out << usage;
                return 0;
              }
            else if (arg == "--print-parameters")
              {
                if (root)
                  Parameters::print_defaults(out);
                return 0;
              }
            else if (arg == "--check")
              check_only = true;
            else if (arg == "-s")
              {
                AssertThrow(i + 1 < arguments.size(),
                            ExcMessage("-s needs an argument "
                                       "\"Section/Name=value\"."));
                overrides.push_back(arguments[++i]);
              }
            else if (!arg.empty() && arg[0] == '-')
              {
                AssertThrow(false,
                            ExcMessage("Unknown option '" + arg +
                                       "' (see ssc --help)."));
              }
            else
              {
                AssertThrow(file.empty(),
                            ExcMessage("More than one parameter file given ('" +
                                       file + "' and '" + arg + "')."));
                file = arg;
              }
          }
        AssertThrow(!file.empty(),
                    ExcMessage("No parameter file given (see ssc --help)."));

        Parameters parameters;
        parameters.read(file, overrides);
        if (check_only)
          {
            if (root)
              out << file << ": parameters are valid" << std::endl;
            return 0;
          }
        switch (parameters.run.scene)
          {
            case SceneKind::indentation:
              IndentationScene(parameters, mpi_communicator).run();
              break;
            case SceneKind::growth:
              GrowthScene(parameters, mpi_communicator).run();
              break;
            case SceneKind::geometry:
              GeometryScene(parameters, mpi_communicator).run();
              break;
          }
        return 0;
      }
    catch (const ExceptionBase &e)
      {
        if (root)
          err << "ssc: error: " << user_message(e) << std::endl;
      }
    catch (const std::exception &e)
      {
        if (root)
          err << "ssc: error: " << e.what() << std::endl;
      }
    return 1;
  }
} // namespace ssc
