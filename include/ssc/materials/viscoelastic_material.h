#ifndef ssc_materials_viscoelastic_material_h
#define ssc_materials_viscoelastic_material_h

#include <memory>

#include <ssc/materials/material.h>
#include <ssc/materials/prony_series.h>

namespace ssc
{
  /**
   * A visco-elastic layer at finite strain: the isochoric part of the law
   * @p inner relaxes by the Prony series, the volumetric energy stays
   * elastic (Simo 1987, CMAME 60:153; Holzapfel 2000, section 6.10). With
   * S_0(C) = F^{-1} tau_0 F^{-T} the inner law's isochoric second Piola
   * stress (its instantaneous response),
   *   S_iso(t) = g_inf S_0(t) + sum_i g_i H_i(t),
   *   H_i(t)   = int_0^t exp(-(t - s) / tau_i) dS_0/ds ds,
   * integrated over a step of length dt with dS_0/ds constant in it (exact
   * for a stress that changes linearly in the step, second order in dt
   * otherwise):
   *   H_i^{n+1} = e_i H_i^n + c_i (S_0^{n+1} - S_0^n),
   *   e_i = exp(-dt / tau_i), c_i = (1 - e_i) / (dt / tau_i).
   * So S_iso = k S_0 + S_h with k = g_inf + sum_i g_i c_i and the fixed
   * S_h = sum_i g_i (e_i H_i^n - c_i S_0^n): the Kirchhoff stress is
   * k tau_0 + F S_h F^T and the spatial tangent k a_0 + delta_ij (F S_h
   * F^T)_kl, exactly consistent. History per point: S_0^n and the H_i^n,
   * 6 (1 + n) values, zero in the stress-free reference state. dt = 0 (a
   * load step without time) is the instantaneous response; dt >> tau_i
   * relaxes term i fully.
   *
   * The layer's E and nu are the instantaneous moduli; the long-term shear
   * modulus is g_inf mu.
   */
  class ViscoelasticMaterial : public Material
  {
  public:
    ViscoelasticMaterial(std::unique_ptr<const Material> inner,
                         PronySeries                     series);

    Kinematics
    kinematics() const override
    {
      return inner->kinematics();
    }

    unsigned int
    n_history_variables() const override
    {
      return 6 * (1 + series.size());
    }

    void
    check_point(const Point<3> &X) const override
    {
      inner->check_point(X);
    }

    /// The instantaneous response (no history: dt = 0 from the reference
    /// state).
    void
    isochoric_response(const Point<3>        &X,
                       const Tensor<2, 3>    &F,
                       SymmetricTensor<2, 3> &tau,
                       Tensor<4, 3>          &tangent) const override
    {
      inner->isochoric_response(X, F, tau, tangent);
    }

    SymmetricTensor<2, 3>
    isochoric_stress(const Point<3> &X, const Tensor<2, 3> &F) const override
    {
      return inner->isochoric_stress(X, F);
    }

    void
    isochoric_response_in_step(const Point<3>        &X,
                               const Tensor<2, 3>    &F,
                               MaterialPointHistory  &history,
                               SymmetricTensor<2, 3> &tau,
                               Tensor<4, 3>          &tangent) const override;

    SymmetricTensor<2, 3>
    isochoric_stress_in_step(const Point<3>       &X,
                             const Tensor<2, 3>   &F,
                             MaterialPointHistory &history) const override;

    /// The instantaneous energy (the inner law's).
    double
    energy(const Point<3> &X, const Tensor<2, 3> &F) const override
    {
      return inner->energy(X, F);
    }

  private:
    /// Writes S_0 and the H_i of the step into @p history.trial and returns
    /// k and the Kirchhoff stress of S_h, F S_h F^T.
    std::pair<double, SymmetricTensor<2, 3>>
    update_history(const Tensor<2, 3>          &F,
                   const SymmetricTensor<2, 3> &tau_0,
                   MaterialPointHistory        &history) const;

    std::unique_ptr<const Material> inner;
    const PronySeries               series;
  };
} // namespace ssc

#endif
