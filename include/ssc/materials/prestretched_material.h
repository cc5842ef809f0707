#ifndef ssc_materials_prestretched_material_h
#define ssc_materials_prestretched_material_h

#include <memory>

#include <ssc/materials/material.h>

namespace ssc
{
  /**
   * A layer whose imaged geometry is not its stress-free one: skin in vivo
   * is pre-tensioned (Langer's lines are its lines of greatest tension). The
   * law @p inner is evaluated at F F_p with the in-plane prestretch
   *   F_p = diag(s, s, 1/s^2),
   * the deformation from the stress-free state to the imaged one (x, y in
   * the plane of the skin). F_p keeps the volume, so J and U(J) are
   * unchanged and, with F_e = F F_p, the Kirchhoff stress and the spatial
   * tangent are the inner law's at F_e (tau = P F^T = P_e F_e^T; a_ikjl =
   * F_kK A_iKjL F_lL = (F_e)_kM A^e_iMjN (F_e)_lN): the wrapper passes them
   * on unchanged.
   *
   * At u = 0 the layer carries the plane pre-stress of F_p, held by the
   * patch's sides; its thickness settles where the volumetric energy takes
   * up the out-of-plane stress (for nearly incompressible layers a change
   * of order sigma / kappa, so the geometry stays where it was imaged to
   * that order, without the iterative update of FEBio's prestrain plugin).
   * Finite-strain laws only: the small-strain kernel would assemble the
   * tangent at F = I and miss the pre-stress.
   *
   * A scene that has to reach the pre-tension gradually (a cut skin, whose
   * wound opens as the tension comes on) ramps it with set_fraction().
   */
  class PrestretchedMaterial : public Material
  {
  public:
    PrestretchedMaterial(std::unique_ptr<const Material> inner,
                         const double                    prestretch);

    Kinematics
    kinematics() const override
    {
      return inner->kinematics();
    }

    unsigned int
    n_history_variables() const override
    {
      return inner->n_history_variables();
    }

    void
    check_point(const Point<3> &X) const override
    {
      inner->check_point(X);
    }

    void
    isochoric_response(const Point<3>        &X,
                       const Tensor<2, 3>    &F,
                       SymmetricTensor<2, 3> &tau,
                       Tensor<4, 3>          &tangent) const override
    {
      inner->isochoric_response(X, F * F_p, tau, tangent);
    }

    SymmetricTensor<2, 3>
    isochoric_stress(const Point<3> &X, const Tensor<2, 3> &F) const override
    {
      return inner->isochoric_stress(X, F * F_p);
    }

    double
    energy(const Point<3> &X, const Tensor<2, 3> &F) const override
    {
      return inner->energy(X, F * F_p);
    }

    SymmetricTensor<2, 3>
    cauchy_stress(const Point<3>     &X,
                  const Tensor<2, 3> &F,
                  const double        gamma = 1.) const override
    {
      return inner->cauchy_stress(X, F * F_p, gamma);
    }

    /// F_p.
    const Tensor<2, 3> &
    prestretch() const
    {
      return F_p;
    }

    /// The prestretch 1 + f (s - 1) instead of s: f = 0 is the stress-free
    /// layer, f = 1 the full pre-tension. Not during an assembly.
    void
    set_fraction(const double f);

  private:
    std::unique_ptr<const Material> inner;
    const double                    full_prestretch;
    Tensor<2, 3>                    F_p;
  };
} // namespace ssc

#endif
