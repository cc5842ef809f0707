#ifndef ssc_materials_gasser_ogden_holzapfel_material_h
#define ssc_materials_gasser_ogden_holzapfel_material_h

#include <deal.II/base/function_parser.h>

#include <array>
#include <memory>
#include <string>

#include <ssc/materials/material.h>
#include <ssc/materials/neo_hookean_material.h>
#include <ssc/materials/volumetric_energy_parameters.h>

namespace ssc
{
  /**
   * The parameters of the fibre-reinforced dermis
   * (GasserOgdenHolzapfelMaterial), "Layer
   * stack/<layer>/Gasser-Ogden-Holzapfel": the fibres' stiffness, exponent,
   * dispersion and angle to Langer's lines, and the lines themselves as an
   * angle map over the skin surface. The defaults are Ní Annaidh et al. 2012's
   * fit to excised human back skin (Ann Biomed Eng 40:1666): k1 243.6 MPa, k2
   * 0.1327, kappa 0.1404 +- 0.0028 from histology, fibres at +-41 degrees to
   * the lines. Their matrix shear modulus (0.2014 MPa, in tension) is not
   * taken: the matrix is the layer's own E and nu, as for every law.
   */
  class GasserOgdenHolzapfelParameters : public VolumetricEnergyParameters
  {
  public:
    void
    add_parameters(ParameterHandler &prm) override;

    /// Throws, naming the entry, if the Langer-line map is not an
    /// expression of x and y or not a number at x = y = 0 (elsewhere the
    /// law's check_point() finds it, at every quadrature point).
    void
    check(const std::string &section) const override;

    /// k1, MPa.
    double fibre_stiffness = 243.6;
    /// k2, dimensionless.
    double fibre_exponent = 0.1327;
    /// kappa in [0, 1/3]: 0 aligned fibres, 1/3 isotropic.
    double fibre_dispersion = 0.1404;
    /// The angle of each of the two families to Langer's lines, degrees.
    double fibre_angle = 41.;
    /// lambda_r >= 1: the stretch at which the wavy fibres become straight
    /// and start to bear load (1: at once, as Ni Annaidh et al. fitted).
    double recruitment_stretch = 1.;
    /// Langer's lines: their angle to the x axis (towards y), degrees, as
    /// a muParser expression of x and y (mm).
    std::string langer_line_angle = "0";
  };


  /**
   * Fibre-reinforced hyperelastic skin: the neo-Hookean matrix of the layer
   * (mu from E and nu, NeoHookeanMaterial) plus two families of collagen
   * fibres in the plane of the skin with the dispersion of Gasser, Ogden
   * and Holzapfel 2006 (J R Soc Interface 3:15):
   *   Psi = mu/2 (I1_bar - 3) + U(J) + sum_i k1/(2 k2) (exp(k2 <E_i>^2) - 1),
   *   E_i = kappa I1 + (1 - 3 kappa) I4i - 1,  I1 = tr C,  I4i = a0i.C a0i,
   * with the Macaulay bracket <E> = max(E, 0): a family bears tension only
   * (the switch on E that Abaqus' HGO law applies, with which the sourced
   * parameters were fitted). The fibres a0i lie in the plane z = const at
   * theta(x, y) +- gamma, theta the Langer lines' angle at the point.
   *
   * The fibre term takes the full invariants of C, not the isochoric ones
   * of Abaqus' form (the "modified anisotropic" model of Nolan et al. 2014,
   * J Mech Behav Biomed Mater 39:48; the deficiency of the isochoric form
   * in Vergori et al. 2013, Comput Mech 52:1185). The fibres are up to 10^4
   * times stiffer than the in vivo matrix, so the bulk modulus of E and nu
   * competes with them: under equibiaxial stretch 1.1 (E = 20 kPa, the
   * sourced fibres) the isochoric form swells (J = 1.07 at nu = 0.49999)
   * and carries 39 MPa instead of the incompressible limit's 62.8 MPa; the
   * full form gives 62.8 MPa with J = 0.97. Both agree as nu -> 1/2, where
   * the parameters were fitted; a layer with fibres needs nu of 0.49999 or
   * closer for its volume to stay nearly constant.
   *
   * In the spatial form the fibres add, with a_i = F a0i and b = F F^T,
   *   tau_f = sum_i 2 psi'_i h_i,  h_i = kappa b + (1 - 3 kappa) a_i (x) a_i,
   *   c_f   = sum_i 4 psi''_i h_i (x) h_i   (plus the geometric part),
   * psi'_i = k1 E_i exp(k2 E_i^2), psi''_i = k1 (1 + 2 k2 E_i^2)
   * exp(k2 E_i^2). At F = I every E_i = 0: the law reduces to the layer's
   * isotropic small-strain moduli, and the fibres join in as soon as they
   * are stretched (the tangent jumps by 4 k1 h (x) h there).
   *
   * A recruitment stretch lambda_r > 1 gives the fibres the toe region of
   * skin's tensile curve (the collagen straightens before it bears load):
   *   E_i = (kappa I1 + (1 - 3 kappa) I4i) / lambda_r^2 - 1,
   * so a family is slack until its pseudo-stretch exceeds lambda_r, and h_i
   * above carries the factor 1 / lambda_r^2. Ni Annaidh et al.'s
   * parameters were fitted from zero strain (lambda_r = 1): with them the
   * fibres are 10^4 times stiffer than the in vivo matrix from the first
   * strain, and an in vivo tension of 6-11 N/m stretches such skin by 2e-5
   * only. lambda_r equal to the skin's prestretch puts the fibres at the
   * end of their toe in vivo: the matrix carries the resting tension, the
   * fibres what a closure or a load adds.
   */
  class GasserOgdenHolzapfelMaterial : public Material
  {
  public:
    GasserOgdenHolzapfelMaterial(
      const IsotropicModuli                &moduli,
      const GasserOgdenHolzapfelParameters &parameters);

    Kinematics
    kinematics() const override
    {
      return Kinematics::finite_strain;
    }

    /// Throws if the Langer-line map is not a number at @p X.
    void
    check_point(const Point<3> &X) const override
    {
      fibre_directions(X);
    }

    void
    isochoric_response(const Point<3>        &X,
                       const Tensor<2, 3>    &F,
                       SymmetricTensor<2, 3> &tau,
                       Tensor<4, 3>          &tangent) const override;

    SymmetricTensor<2, 3>
    isochoric_stress(const Point<3> &X, const Tensor<2, 3> &F) const override;

    double
    energy(const Point<3> &X, const Tensor<2, 3> &F) const override;

    /// The two fibre directions (unit, reference configuration) at @p X.
    std::array<Tensor<1, 3>, 2>
    fibre_directions(const Point<3> &X) const;

  private:
    /// The fibres' Kirchhoff stress tau_f at @p F and, if @p fibre_tangent
    /// is given, c_f without its geometric part.
    SymmetricTensor<2, 3>
    fibre_stress(const Point<3>        &X,
                 const Tensor<2, 3>    &F,
                 SymmetricTensor<4, 3> *fibre_tangent) const;

    const NeoHookeanMaterial matrix;
    const double             k1;
    const double             k2;
    const double             kappa;
    /// 1 / lambda_r^2.
    const double recruitment;
    /// gamma, radians.
    const double                       fibre_angle;
    std::shared_ptr<FunctionParser<2>> langer_line_angle;
  };
} // namespace ssc

#endif
