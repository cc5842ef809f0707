#ifndef ssc_materials_volumetric_energy_h
#define ssc_materials_volumetric_energy_h

#include <array>
#include <cmath>
#include <utility>

namespace ssc
{
  /// Which function of J the volumetric energy is (VolumetricEnergy).
  enum class VolumetricEnergyForm
  {
    /// kappa/4 (J^2 - 1 - 2 ln J) (Simo and Taylor 1982)
    logarithmic,
    /// kappa/2 (J - 1)^2 (CalculiX's and Abaqus' NEO HOOKE with D1 =
    /// 2/kappa: what a peer code solves)
    quadratic
  };

  constexpr std::array<std::pair<VolumetricEnergyForm, const char *>, 2>
  enum_table(VolumetricEnergyForm)
  {
    return {{{VolumetricEnergyForm::logarithmic, "logarithmic"},
             {VolumetricEnergyForm::quadratic, "quadratic"}}};
  }

  /**
   * Volumetric strain energy U(J) shared by the finite-strain laws. Both
   * forms equal kappa/2 (J - 1)^2 to second order, so the laws agree with
   * linear elasticity at small strain; they part where the fat is driven
   * far from J = 1 (at nu = 0.49 under a punch). The logarithmic form (the
   * default) grows without bound as J -> 0 (no inversion); the quadratic
   * one stays finite there and is what peer codes offer. The finite-strain
   * kernel evaluates it per quadrature point (displacement formulation) or
   * at the projected dilatation of the mixed formulations.
   */
  class VolumetricEnergy
  {
  public:
    explicit VolumetricEnergy(
      const double               bulk_modulus,
      const VolumetricEnergyForm form = VolumetricEnergyForm::logarithmic)
      : kappa(bulk_modulus)
      , form(form)
    {}

    /// U'(J): the pressure.
    double
    pressure(const double J) const
    {
      return form == VolumetricEnergyForm::logarithmic ?
               0.5 * kappa * (J - 1. / J) :
               kappa * (J - 1.);
    }

    /// U''(J).
    double
    pressure_derivative(const double J) const
    {
      return form == VolumetricEnergyForm::logarithmic ?
               0.5 * kappa * (1. + 1. / (J * J)) :
               kappa;
    }

    /// U(J).
    double
    volumetric_energy(const double J) const
    {
      return form == VolumetricEnergyForm::logarithmic ?
               0.25 * kappa * (J * J - 1. - 2. * std::log(J)) :
               0.5 * kappa * (J - 1.) * (J - 1.);
    }

    /// Bulk modulus, MPa.
    const double kappa;

    const VolumetricEnergyForm form;
  };
} // namespace ssc

#endif
