#ifndef ssc_materials_volumetric_energy_h
#define ssc_materials_volumetric_energy_h

#include <cmath>

namespace ssc
{
  /**
   * Volumetric strain energy U(J) = kappa/4 (J^2 - 1 - 2 ln J) shared by
   * the finite-strain laws: it grows without bound as J -> 0 (no
   * inversion) and equals kappa/2 (J - 1)^2 to second order, so the laws
   * agree with linear elasticity at small strain. The finite-strain kernel
   * evaluates it per quadrature point (displacement formulation) or at the
   * projected dilatation of the mixed formulations.
   */
  class VolumetricEnergy
  {
  public:
    explicit VolumetricEnergy(const double bulk_modulus)
      : kappa(bulk_modulus)
    {}

    /// U'(J): the pressure.
    double
    pressure(const double J) const
    {
      return 0.5 * kappa * (J - 1. / J);
    }

    /// U''(J).
    double
    pressure_derivative(const double J) const
    {
      return 0.5 * kappa * (1. + 1. / (J * J));
    }

    /// U(J).
    double
    volumetric_energy(const double J) const
    {
      return 0.25 * kappa * (J * J - 1. - 2. * std::log(J));
    }

    /// Bulk modulus, MPa.
    const double kappa;
  };
} // namespace ssc

#endif
