#include <deal.II/base/conditional_ostream.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include <ssc/embedding/point_locator.h>
#include <ssc/identification/probe_forward_model.h>
#include <ssc/mesh/mesh_parameters.h>
#include <ssc/scenes/indentation_output.h>
#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/punch_loading.h>
#include <ssc/scenes/quasi_static_driver.h>

namespace ssc
{
  namespace
  {
    std::string
    setting(const std::string &entry, const double value)
    {
      std::ostringstream text;
      text << entry << '=' << std::setprecision(17) << value;
      return text.str();
    }
  } // namespace


  ProbeForwardModel::ProbeForwardModel(const Parameters &parameters,
                                       TimerOutput      &timer)
    : parameters(parameters)
    , timer(timer)
  {}


  std::pair<double, double>
  ProbeForwardModel::probe_face(const IndentationTrial &trial)
  {
    for (const auto &[length, width] :
         {std::pair(45., 8.), std::pair(45., 15.)})
      if (std::abs(trial.probe_area - length * width) < 0.02 * length * width)
        return {length, width};
    std::ostringstream message;
    message << "Line " << trial.line << " of the data (subject "
            << trial.subject << ", " << trial.site << "): probe area "
            << trial.probe_area
            << " mm^2 is neither the 14L5's (45 x 8 = 360 mm^2) nor the "
               "9L4's (45 x 15 = 675 mm^2) face.";
    AssertThrow(false, ExcMessage(message.str()));
    return {0, 0};
  }


  void
  ProbeForwardModel::check_trial(const IndentationTrial &trial,
                                 const double            patch_margin)
  {
    const double length = probe_face(trial).first;
    const double patch_length =
      length + 2 * patch_margin * trial.total_thickness();
    std::ostringstream message;
    message << "Line " << trial.line << " of the data (subject "
            << trial.subject << ", " << trial.site << "): a patch of "
            << "Identification/Patch margin = " << patch_margin << " times "
            << "the tissue thickness " << trial.total_thickness()
            << " mm beyond the probe would be " << patch_length
            << " mm long, more than the " << MeshParameters::max_patch_length
            << " mm a model may be: lower the Patch margin or check the "
               "line's thicknesses.";
    AssertThrow(patch_length <= MeshParameters::max_patch_length,
                ExcMessage(message.str()));
  }


  std::vector<std::string>
  ProbeForwardModel::overrides(const IndentationTrial      &trial,
                               const std::array<double, 3> &moduli) const
  {
    std::vector<std::string> result = parameters.overrides();
    const auto [length, width]      = probe_face(trial);
    const double margin =
      parameters.identification.patch_margin * trial.total_thickness();
    const std::array<double, 3> thicknesses = trial.layer_thicknesses();
    for (unsigned int l = 0; l < 3; ++l)
      {
        const std::string layer =
          "Layer stack/" + parameters.layers.layer(l).name + '/';
        result.push_back(setting(layer + "Thickness", thicknesses[l]));
        result.push_back(setting(layer + "Young's modulus", moduli[l]));
      }
    result.push_back(setting("Punch/Length", length));
    result.push_back(setting("Punch/Width", width));
    result.push_back(setting("Mesh/Patch length x", length + 2 * margin));
    result.push_back(setting("Mesh/Patch length y", width + 2 * margin));
    result.push_back(setting("Mesh/Core half width", length / 2));
    result.push_back(setting("Mesh/Core half width y", width / 2));
    for (const char *entry : {"Run/Scene=indentation",
                              "Run/Write fields=false",
                              "Punch/Forces=1",
                              "Punch/Profile length=0",
                              "Punch/Section=false"})
      result.emplace_back(entry);
    return result;
  }


  ProbeResponse
  ProbeForwardModel::solve(const IndentationTrial      &trial,
                           const std::array<double, 3> &moduli) const
  {
    Parameters model_parameters;
    model_parameters.read(parameters.file(), overrides(trial, moduli));

    ConditionalOStream silent(std::cout, false);
    MechanicsModel     model(
      model_parameters, MPI_COMM_SELF, timer, silent, silent);
    ElasticSystem     &system = model.system();
    PunchLoading       loading(model_parameters, system, timer, silent);
    QuasiStaticDriver  driver(system, model_parameters.newton, silent, false);
    const PointLocator locator(model.mesh().triangulation(),
                               system.field().mapping());
    const CentreAxisStrains centre_axis(model_parameters.layers, locator);

    ProbeResponse response;
    response.dofs  = system.field().dof_handler().n_dofs();
    response.cells = model.mesh().triangulation().n_global_active_cells();
    driver.run(
      {1.},
      [&loading](const double force) { loading.apply(force); },
      1.,
      LoadDependence::right_hand_side,
      [&](const unsigned int) {
        response.stiffness = 1. / loading.depth(1.);
        const auto strains = centre_axis.evaluate(system.field());
        for (unsigned int l = 0; l < 3; ++l)
          response.strains_per_newton[l] = strains[l];
      });
    return response;
  }
} // namespace ssc
