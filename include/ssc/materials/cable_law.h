#ifndef ssc_materials_cable_law_h
#define ssc_materials_cable_law_h

#include <deal.II/base/tensor.h>

#include <ssc/materials/material.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The law of a cable (a ligament) of cross-section A and modulus E, per
   * unit reference length: W = (E A / 2) e^2 with the axial strain e (small
   * strain: tau . eps tau for the unit tangent tau; finite strain: the
   * Green strain (|F tau|^2 - 1) / 2), optionally tension-only (a
   * compressed cable is slack and carries nothing).
   */
  class CableLaw
  {
  public:
    CableLaw(const double youngs_modulus,
             const double area,
             const bool   tension_only)
      : axial_stiffness(youngs_modulus * area)
      , tension_only(tension_only)
    {}

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
    /// @p tangent: E A e |F tau| with the Green strain e at finite strain,
    /// E A tau . eps tau at small strain.
    double
    current_force(const Tensor<2, 3> &F,
                  const Tensor<1, 3> &tangent,
                  const Kinematics    kinematics) const
    {
      const Tensor<1, 3> a = F * tangent;
      if (kinematics == Kinematics::small_strain)
        return axial_stiffness * (tangent * (a - tangent));
      return axial_force(0.5 * (a * a - 1.)) * a.norm();
    }

  private:
    const double axial_stiffness;
    const bool   tension_only;
  };
} // namespace ssc

#endif
