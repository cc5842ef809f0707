#ifndef ssc_materials_material_registry_h
#define ssc_materials_material_registry_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <ssc/materials/isotropic_moduli.h>
#include <ssc/materials/material.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The parameters a law adds to its layer, beyond the small-strain moduli E
   * and nu that every law reduces to at F = I (Layer). Each law declares
   * them, bound to its own members, in the subsection "Layer
   * stack/<layer>/<law name>" (as ASPECT's plugins or FEBio's
   * ADD_PARAMETER do), so that a new law brings its parameters along
   * instead of widening the layer.
   */
  class MaterialParameters
  {
  public:
    virtual ~MaterialParameters() = default;

    /// Declares the law's entries in the current subsection, bound to the
    /// members of this object (ParameterHandler::add_parameter).
    virtual void
    add_parameters(ParameterHandler &prm) = 0;

    /// Whether add_parameters() declares anything (no empty subsection in
    /// the manual otherwise).
    virtual bool
    has_entries() const
    {
      return true;
    }

    /// Throws, naming @p section (the subsection's path), if the values
    /// cannot make a law; the patterns have checked each value already.
    virtual void
    check(const std::string &section) const
    {
      (void)section;
    }
  };


  /// The parameters of a law that has none of its own.
  class NoMaterialParameters : public MaterialParameters
  {
  public:
    void
    add_parameters(ParameterHandler &) override
    {}

    bool
    has_entries() const override
    {
      return false;
    }
  };


  /**
   * Every constitutive law of ssc by name: how to make its parameters and
   * how to make the law from the layer's moduli and those parameters. A law
   * registers itself in its own source file (register_material()), so that
   * a new law is one file and its case in tests/material_tangent.cc, which
   * checks every registered law.
   *
   * The table is filled while the library loads (each law's registration is
   * a constant of its file) and only read afterwards; it is reached through
   * a function (construct on first use), so that the order in which the
   * library's files are initialised does not matter.
   */
  class MaterialRegistry
  {
  public:
    using ParameterFactory =
      std::function<std::unique_ptr<MaterialParameters>()>;
    using LawFactory = std::function<
      std::unique_ptr<Material>(const IsotropicModuli    &moduli,
                                const MaterialParameters &parameters)>;

    struct Entry
    {
      /// The value of "Material model" that selects the law.
      std::string name;
      /// One or two sentences for the manual: what the law is, when to
      /// use it.
      std::string      description;
      ParameterFactory make_parameters;
      LawFactory       make_law;
    };

    /// Adds @p entry; throws if its name is taken. Returns true, so that a
    /// registration can initialise a constant.
    static bool
    add(Entry entry);

    /// The law called @p name; throws, naming @p parameter (the entry that
    /// gave the name) and the registered laws, if there is none.
    static const Entry &
    get(const std::string &name, const std::string &parameter);

    /// The registered names, sorted.
    static std::vector<std::string>
    names();

    /// "name: description" of every law, for documentation strings.
    static std::string
    documentation();

  private:
    static std::vector<Entry> &
    entries();
  };


  /**
   * Registers @p Law under @p name: @p Law is constructed from the layer's
   * IsotropicModuli and its @p LawParameters (a MaterialParameters).
   * Used once per law, at namespace scope in the law's source file:
   * @code
   * const bool registered = register_material<MyLaw, MyLawParameters>(
   *   "my law", "What it is and when to use it.");
   * @endcode
   */
  template <class Law, class LawParameters = NoMaterialParameters>
  bool
  register_material(const std::string &name, const std::string &description)
  {
    return MaterialRegistry::add(
      {name,
       description,
       []() { return std::make_unique<LawParameters>(); },
       [](const IsotropicModuli    &moduli,
          const MaterialParameters &parameters) -> std::unique_ptr<Material> {
         return std::make_unique<Law>(
           moduli, dynamic_cast<const LawParameters &>(parameters));
       }});
  }
} // namespace ssc

#endif
