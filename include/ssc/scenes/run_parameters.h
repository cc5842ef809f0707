#ifndef ssc_scenes_run_parameters_h
#define ssc_scenes_run_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>

#include <ssc/base/enum_table.h>

namespace ssc
{
  using namespace dealii;

  /// What a run simulates.
  enum class SceneKind
  {
    indentation,
    growth,
    geometry,
    identification,
    incision
  };

  constexpr std::array<std::pair<SceneKind, const char *>, 5>
  enum_table(SceneKind)
  {
    return {{{SceneKind::indentation, "indentation"},
             {SceneKind::growth, "growth"},
             {SceneKind::geometry, "geometry"},
             {SceneKind::identification, "identification"},
             {SceneKind::incision, "incision"}}};
  }

  /// Section "Run": which scene, where its results go.
  struct RunParameters
  {
    SceneKind   scene            = SceneKind::indentation;
    std::string name             = "indentation";
    std::string output_directory = "output";
    bool        test_mode        = false;
    bool        write_fields     = true;

    /// Declares section "Run", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;
  };
} // namespace ssc

#endif
