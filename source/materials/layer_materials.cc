#include <ssc/materials/layer_materials.h>
#include <ssc/materials/prestretched_material.h>
#include <ssc/materials/viscoelastic_material.h>

namespace ssc
{
  LayerLawParameters::LayerLawParameters()
  {
    for (const std::string &law : MaterialRegistry::names())
      defaults[law] = MaterialRegistry::get(law, "").make_parameters();
  }


  void
  LayerLawParameters::add_parameters(
    ParameterHandler               &prm,
    const std::vector<std::string> &layer_names)
  {
    prm.enter_subsection("Layer stack");
    for (const std::string &layer : layer_names)
      {
        prm.enter_subsection(layer);
        for (const std::string &law : MaterialRegistry::names())
          {
            auto parameters = MaterialRegistry::get(law, "").make_parameters();
            if (parameters->has_entries())
              {
                prm.enter_subsection(law);
                parameters->add_parameters(prm);
                prm.leave_subsection();
              }
            per_layer[layer][law] = std::move(parameters);
          }
        prm.add_parameter(
          "Volumetric energy",
          moved_volumetric_energy[layer],
          "Moved: the finite-strain laws own it now, as 'Layer "
          "stack/<layer>/<law>/Volumetric energy' (e.g. subsection "
          "neo-Hookean). Setting it here is an error that says so.",
          Patterns::Anything());
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  void
  LayerLawParameters::check(const LayerStack &layers) const
  {
    for (const auto &[layer, value] : moved_volumetric_energy)
      AssertThrow(value.empty(),
                  ExcMessage("'Layer stack/" + layer +
                             "/Volumetric energy' has moved into the law "
                             "that owns it: write it as 'Layer stack/" +
                             layer +
                             "/<law>/Volumetric energy', e.g. "
                             "subsection " +
                             layer +
                             " / subsection neo-Hookean / set Volumetric "
                             "energy = " +
                             value + "."));
    for (unsigned int l = 0; l < layers.n_layers(); ++l)
      {
        const Layer      &layer = layers.layer(l);
        const std::string path  = "Layer stack/" + layer.name + "/";
        MaterialRegistry::get(layer.material_model, path + "Material model");
        prony_series(layer).check(path + "Viscoelasticity/");
        of(layer.name, layer.material_model).check(path + layer.material_model);
      }
  }


  const MaterialParameters &
  LayerLawParameters::of(const std::string &layer, const std::string &law) const
  {
    const auto declared = per_layer.find(layer);
    if (declared != per_layer.end() && declared->second.count(law) > 0)
      return *declared->second.at(law);
    MaterialRegistry::get(law, "Material model");
    return *defaults.at(law);
  }


  PronySeries
  prony_series(const Layer &layer)
  {
    return {layer.relative_moduli, layer.relaxation_times};
  }


  std::unique_ptr<Material>
  make_material(const Layer &layer, const LayerLawParameters &laws)
  {
    const MaterialRegistry::Entry &entry =
      MaterialRegistry::get(layer.material_model,
                            "Layer stack/" + layer.name + "/Material model");
    auto law =
      entry.make_law(IsotropicModuli(layer.youngs_modulus, layer.poisson_ratio),
                     laws.of(layer.name, layer.material_model));
    if (const PronySeries series = prony_series(layer); !series.empty())
      {
        const std::string path = "Layer stack/" + layer.name + "/";
        AssertThrow(
          law->kinematics() == Kinematics::finite_strain,
          ExcMessage(path + "Viscoelasticity needs a finite-strain law: '" +
                     layer.material_model + "' is assembled at small strain."));
        AssertThrow(layer.prestretch == 1.,
                    ExcMessage(path + "Viscoelasticity and " + path +
                               "Prestretch cannot be combined yet: the "
                               "history starts stress-free, so the in vivo "
                               "pre-tension would relax over time."));
        series.check(path + "Viscoelasticity/");
        return std::make_unique<ViscoelasticMaterial>(std::move(law), series);
      }
    if (layer.prestretch == 1.)
      return law;
    AssertThrow(law->kinematics() == Kinematics::finite_strain,
                ExcMessage("Layer stack/" + layer.name +
                           "/Prestretch needs a finite-strain law: '" +
                           layer.material_model +
                           "' is assembled at small strain, which would "
                           "miss the pre-stress."));
    return std::make_unique<PrestretchedMaterial>(std::move(law),
                                                  layer.prestretch);
  }


  LayerMaterials::LayerMaterials(const LayerStack         &layers,
                                 const LayerLawParameters &laws)
  {
    for (unsigned int l = 0; l < layers.n_layers(); ++l)
      {
        std::unique_ptr<Material> law = make_material(layers.layer(l), laws);
        if (auto *p = dynamic_cast<PrestretchedMaterial *>(law.get()))
          prestretched.push_back(p);
        materials.push_back(std::move(law));
      }
  }


  void
  LayerMaterials::set_prestretch_fraction(const double f)
  {
    for (PrestretchedMaterial *law : prestretched)
      law->set_fraction(f);
  }


  bool
  LayerMaterials::any_finite_strain() const
  {
    for (const auto &material : materials)
      if (material->kinematics() == Kinematics::finite_strain)
        return true;
    return false;
  }
} // namespace ssc
