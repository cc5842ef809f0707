#ifndef ssc_materials_material_h
#define ssc_materials_material_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>

#include <ssc/materials/isotropic_moduli.h>
#include <ssc/materials/volumetric_energy.h>

namespace ssc
{
  using namespace dealii;

  /// Which cell kernel assembles a law.
  enum class Kinematics
  {
    /// linear in the displacement gradient (small strain)
    small_strain,
    /// a function of the deformation gradient F (finite strain)
    finite_strain
  };

  /**
   * What a law with history (Material::n_history_variables() > 0) sees at
   * its material point while a load or time step is solved: the values of
   * the last accepted step, where to write this step's values, and the
   * step's length in time (s; 0 for a load step without time: the law
   * answers instantly). The mechanics keeps both copies (QuadratureHistory).
   */
  struct MaterialPointHistory
  {
    ArrayView<const double> committed;
    ArrayView<double>       trial;
    double                  time_step = 0;
  };


  /**
   * The constitutive law of one layer: stress and consistent tangent from
   * the deformation gradient F, split into the volumetric energy U(J)
   * (VolumetricEnergy), which the mixed formulations evaluate at the
   * projected dilatation, and the rest of the energy, called the isochoric
   * part: a function of J^{-1/3} F alone for the isotropic laws; the fibre
   * term of the fibre-reinforced law also sees the volume change (its
   * header says why).
   *
   * The isochoric part is given in the spatial form the finite-strain kernel
   * assembles: the Kirchhoff stress tau = P F^T and the spatial tangent
   *   a_{ikjl} = F_{kK} (dP_{iK} / dF_{jL}) F_{lL}
   * (geometric part included), so that the linearised virtual work is
   * grad(du)_{ik} a_{ikjl} grad(Du)_{jl} with current gradients. A law
   * written in the first Piola form converts with push_forward().
   *
   * Growth (F = F_e F_g with F_g = gamma^{1/3} I and the energy gamma W(F_e)):
   * the kernel evaluates the isochoric part at F_e = gamma^{-1/3} F and
   * scales its stress and spatial tangent by gamma (tau = gamma tau(F_e),
   * a = gamma a(F_e)), which holds for every law; U sees J_e = J / gamma.
   *
   * Every response takes the reference position X of the material point:
   * a law with a field (fibre directions along Langer's lines) evaluates it
   * there; the uniform laws ignore it.
   *
   * A new law is one class derived from this one, registered in its own
   * source file (register_material(), materials/material_registry.h) with
   * the parameters it owns; tests/material_tangent.cc checks every
   * registered law. A law that keeps history per quadrature point (visco-
   * elasticity, damage) says how many values (n_history_variables()); the
   * mechanics keeps them in a QuadratureHistory.
   */
  class Material
  {
  public:
    explicit Material(const IsotropicModuli     &moduli,
                      const VolumetricEnergyForm volumetric_form =
                        VolumetricEnergyForm::logarithmic);

    virtual ~Material() = default;

    virtual Kinematics
    kinematics() const = 0;

    /// Number of history variables per quadrature point (internal
    /// variables of the law, committed at each accepted load or time step);
    /// 0 for an elastic law.
    virtual unsigned int
    n_history_variables() const
    {
      return 0;
    }

    /// Throws, saying where, if the law cannot be evaluated at the material
    /// point @p X (a field of the law, such as a fibre map, undefined
    /// there). The mechanics calls it at every quadrature point before the
    /// first assembly, so that a bad field is a message, not an exception
    /// inside the threaded assembly. Nothing to check for a uniform law.
    virtual void
    check_point(const Point<3> &X) const
    {
      (void)X;
    }

    /// Isochoric Kirchhoff stress @p tau and spatial tangent @p tangent per
    /// unit reference volume at @p F (det F > 0) at the material point of
    /// reference position @p X.
    virtual void
    isochoric_response(const Point<3>        &X,
                       const Tensor<2, 3>    &F,
                       SymmetricTensor<2, 3> &tau,
                       Tensor<4, 3>          &tangent) const = 0;

    /// The isochoric Kirchhoff stress alone, what a residual needs. By
    /// default taken from isochoric_response(); a law overrides it where
    /// the tangent costs more than the stress (a residual assembly is half
    /// of a Newton iteration's assemblies).
    virtual SymmetricTensor<2, 3>
    isochoric_stress(const Point<3> &X, const Tensor<2, 3> &F) const;

    /// isochoric_response() of a law with history at the end of a step:
    /// reads @p history.committed, writes @p history.trial (the values the
    /// step would commit at this F). The kernel calls it for the laws with
    /// history only; by default the elastic response.
    virtual void
    isochoric_response_in_step(const Point<3>        &X,
                               const Tensor<2, 3>    &F,
                               MaterialPointHistory  &history,
                               SymmetricTensor<2, 3> &tau,
                               Tensor<4, 3>          &tangent) const
    {
      (void)history;
      isochoric_response(X, F, tau, tangent);
    }

    /// isochoric_stress() of a law with history at the end of a step (see
    /// isochoric_response_in_step()).
    virtual SymmetricTensor<2, 3>
    isochoric_stress_in_step(const Point<3>       &X,
                             const Tensor<2, 3>   &F,
                             MaterialPointHistory &history) const
    {
      (void)history;
      return isochoric_stress(X, F);
    }

    /// Strain energy per unit reference volume at @p F at @p X: the
    /// isochoric part plus U(J).
    virtual double
    energy(const Point<3> &X, const Tensor<2, 3> &F) const = 0;

    /// Cauchy stress at @p F at @p X with the growth ratio @p gamma = 1 + g
    /// (stress-free volume change; small-strain laws: sigma of sym(F - I)
    /// less the eigenstrain): the one stress function that output, section
    /// sampling and the scenes use.
    virtual SymmetricTensor<2, 3>
    cauchy_stress(const Point<3>     &X,
                  const Tensor<2, 3> &F,
                  const double        gamma = 1.) const;

    /// cauchy_stress() of a law with history in its last accepted state,
    /// whose history values are @p committed (what the output shows); the
    /// elastic cauchy_stress() for a law without history.
    SymmetricTensor<2, 3>
    accepted_cauchy_stress(const Point<3>                &X,
                           const Tensor<2, 3>            &F,
                           const double                   gamma,
                           const ArrayView<const double> &committed) const;

    /// The tangent of the isochoric part at F = I, minor-symmetric: what the
    /// small-strain kernel assembles (with the bulk modulus on the
    /// volumetric strain). Taken at the origin: every law here is isotropic
    /// and uniform at F = I (fibres that bear tension only are slack there).
    SymmetricTensor<4, 3>
    small_strain_tangent() const;

    const VolumetricEnergy &
    volumetric() const
    {
      return volumetric_energy;
    }

    /// The small-strain moduli the law reduces to at F = I.
    const IsotropicModuli &
    moduli() const
    {
      return reference_moduli;
    }

  protected:
    /// The Cauchy stress from the isochoric Kirchhoff stress @p tau_iso at
    /// F_e, with J = det F and the growth ratio @p gamma.
    SymmetricTensor<2, 3>
    grown_cauchy_stress(const SymmetricTensor<2, 3> &tau_iso,
                        const double                 J,
                        const double                 gamma) const;

    const IsotropicModuli  reference_moduli;
    const VolumetricEnergy volumetric_energy;
  };


  /// The elastic part F_e = F F_g^{-1} of @p F under the growth F_g =
  /// gamma^{1/3} I (@p gamma = 1 + g): where the kernel and cauchy_stress()
  /// evaluate a law (Material).
  inline Tensor<2, 3>
  elastic_part(const Tensor<2, 3> &F, const double gamma)
  {
    return gamma == 1. ? F : std::cbrt(1. / gamma) * F;
  }


  /**
   * The spatial form of a law given in the first Piola form: from the
   * stress @p P and its derivative @p A (A_{iKjL} = dP_{iK} / dF_{jL}) at
   * @p F, the Kirchhoff stress @p tau = P F^T and the spatial tangent
   * @p tangent of Material::isochoric_response().
   */
  void
  push_forward(const Tensor<2, 3>    &F,
               const Tensor<2, 3>    &P,
               const Tensor<4, 3>    &A,
               SymmetricTensor<2, 3> &tau,
               Tensor<4, 3>          &tangent);

  /// von Mises equivalent stress of @p sigma.
  double
  von_mises(const SymmetricTensor<2, 3> &sigma);
} // namespace ssc

#endif
