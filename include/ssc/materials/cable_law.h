#ifndef ssc_materials_cable_law_h
#define ssc_materials_cable_law_h

#include <deal.II/base/tensor.h>

#include <cmath>

#include <ssc/materials/material.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The law of a cable (a ligament) of cross-section A and modulus E, per
   * unit reference length: W = (E A / 2) e^2 with the axial strain e (small
   * strain: tau . eps tau for the unit tangent tau; finite strain: the
   * Green strain (|F tau|^2 / lambda_0^2 - 1) / 2 from its stress-free
   * length, lambda_0 times the reference length: lambda_0 < 1 is a
   * contracted cable), optionally tension-only (a compressed cable is slack
   * and carries nothing).
   */
  class CableLaw
  {
  public:
    CableLaw(const double youngs_modulus,
             const double area,
             const bool   tension_only,
             const double rest_stretch = 1.)
      : axial_stiffness(youngs_modulus * area)
      , tension_only(tension_only)
      , inverse_rest_square(1. / (rest_stretch * rest_stretch))
    {}

    /// The Green strain from the stress-free length for |F tau|^2 = @p aa.
    double
    strain(const double aa) const
    {
      return 0.5 * (aa * inverse_rest_square - 1.);
    }

    /// d strain / d (aa / 2) = 1 / lambda_0^2.
    double
    strain_scale() const
    {
      return inverse_rest_square;
    }

    /// E A (N).
    double
    stiffness() const
    {
      return axial_stiffness;
    }

    /// Whether the cable carries nothing at axial strain @p e.
    bool
    slack(const double e) const
    {
      return tension_only && e < 0;
    }

    /// dW/de = E A e (0 when slack), N.
    double
    axial_force(const double e) const
    {
      return slack(e) ? 0. : axial_stiffness * e;
    }

    /// The force (N) the cable carries in the current configuration at the
    /// background deformation gradient @p F for the unit reference tangent
    /// @p tangent: E A e |F tau| / lambda_0 with the Green strain e at
    /// finite strain, E A tau . eps tau at small strain.
    double
    current_force(const Tensor<2, 3> &F,
                  const Tensor<1, 3> &tangent,
                  const Kinematics    kinematics) const
    {
      const Tensor<1, 3> a = F * tangent;
      if (kinematics == Kinematics::small_strain)
        return axial_stiffness * (tangent * (a - tangent));
      return axial_force(strain(a * a)) * a.norm() *
             std::sqrt(inverse_rest_square);
    }

  private:
    const double axial_stiffness;
    const bool   tension_only;
    const double inverse_rest_square;
  };
} // namespace ssc

#endif
