#ifndef ssc_materials_isotropic_moduli_h
#define ssc_materials_isotropic_moduli_h

#include <deal.II/base/exceptions.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The moduli of isotropic linear elasticity from Young's modulus E and
   * Poisson's ratio nu: the one place where they are converted (volume
   * laws, membranes and output all take them from here).
   */
  struct IsotropicModuli
  {
    IsotropicModuli(const double youngs_modulus, const double poisson_ratio)
      : youngs_modulus(youngs_modulus)
      , poisson_ratio(poisson_ratio)
      , shear_modulus(youngs_modulus / (2. * (1. + poisson_ratio)))
      , lambda(youngs_modulus * poisson_ratio /
               ((1. + poisson_ratio) * (1. - 2. * poisson_ratio)))
      , bulk_modulus(youngs_modulus / (3. * (1. - 2. * poisson_ratio)))
      , plane_stress_lambda(youngs_modulus * poisson_ratio /
                            (1. - poisson_ratio * poisson_ratio))
    {
      Assert(youngs_modulus > 0, ExcMessage("E must be positive."));
      Assert(poisson_ratio > -1 && poisson_ratio < 0.5,
             ExcMessage("nu must lie in (-1, 0.5)."));
    }

    double youngs_modulus; ///< E, MPa
    double poisson_ratio;  ///< nu
    double shear_modulus;  ///< mu = E / (2 (1 + nu)), MPa
    double lambda;         ///< Lamé's first parameter, MPa
    double bulk_modulus;   ///< kappa = lambda + 2 mu / 3, MPa
    /// lambda of plane stress, E nu / (1 - nu^2) = 2 lambda mu / (lambda +
    /// 2 mu) (membranes), MPa
    double plane_stress_lambda;
  };
} // namespace ssc

#endif
