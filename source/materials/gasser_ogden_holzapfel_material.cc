#include <deal.II/base/numbers.h>

#include <cmath>

#include <ssc/base/surface_expression.h>
#include <ssc/materials/gasser_ogden_holzapfel_material.h>

namespace ssc
{
  void
  GasserOgdenHolzapfelParameters::add_parameters(ParameterHandler &prm)
  {
    VolumetricEnergyParameters::add_parameters(prm);
    prm.add_parameter(
      "Fibre stiffness",
      fibre_stiffness,
      "k1 (MPa) of the collagen fibres' energy k1/(2 k2) (exp(k2 E^2) - 1). "
      "243.6 MPa: Ni Annaidh et al. 2012 (Ann Biomed Eng 40:1666), human "
      "back skin in uniaxial tension.",
      Patterns::Double(0.));
    prm.add_parameter("Fibre exponent",
                      fibre_exponent,
                      "k2 (dimensionless): how fast the fibres stiffen. "
                      "0.1327: Ni Annaidh et al. 2012.",
                      Patterns::Double(0.));
    prm.add_parameter(
      "Fibre dispersion",
      fibre_dispersion,
      "kappa in [0, 1/3]: 0 for fibres all along their mean direction, 1/3 "
      "for an isotropic distribution. 0.1404 +- 0.0028: Ni Annaidh et al. "
      "2012, from histology of the dermis.",
      Patterns::Double(0., 1. / 3.));
    prm.add_parameter(
      "Fibre angle",
      fibre_angle,
      "The angle (degrees) of each of the two fibre families to Langer's "
      "lines, in the plane of the skin (+-gamma). 41: Ni Annaidh et al. 2012.",
      Patterns::Double(0., 90.));
    prm.add_parameter(
      "Fibre recruitment stretch",
      recruitment_stretch,
      "lambda_r >= 1: the fibres are slack until their pseudo-stretch "
      "(kappa I1 + (1 - 3 kappa) I4)^(1/2) exceeds it, the toe region of "
      "skin's tensile curve. 1: they bear load from zero strain, as Ni "
      "Annaidh et al. 2012 fitted them. Skin's toe region ends at strains "
      "of about 0.1-0.3 in uniaxial tension (reviewed by Joodaki & Panzer "
      "2018, Proc Inst Mech Eng H 232:323); the prestretch of the layer "
      "puts the fibres at the end of it in vivo.",
      Patterns::Double(1.));
    prm.add_parameter(
      "Langer line angle",
      langer_line_angle,
      "The angle (degrees) of Langer's lines to the x axis, turning towards "
      "y: a number or a muParser expression of x and y (mm), the map of the "
      "lines over the region's skin.",
      Patterns::Anything());
  }


  void
  GasserOgdenHolzapfelParameters::check(const std::string &section) const
  {
    const std::string parameter = section + "/Langer line angle";
    const double      theta =
      parse_surface_expression(langer_line_angle, parameter)->value(Point<2>());
    AssertThrow(std::isfinite(theta),
                ExcMessage(parameter + " = '" + langer_line_angle +
                           "' is not a number at x = y = 0."));
  }


  GasserOgdenHolzapfelMaterial::GasserOgdenHolzapfelMaterial(
    const IsotropicModuli                &moduli,
    const GasserOgdenHolzapfelParameters &parameters)
    : Material(moduli, parameters.form)
    , matrix(moduli, parameters)
    , k1(parameters.fibre_stiffness)
    , k2(parameters.fibre_exponent)
    , kappa(parameters.fibre_dispersion)
    , recruitment(
        1. / (parameters.recruitment_stretch * parameters.recruitment_stretch))
    , fibre_angle(parameters.fibre_angle * numbers::PI / 180.)
    , langer_line_angle(parse_surface_expression(parameters.langer_line_angle,
                                                 "Langer line angle"))
  {}


  std::array<Tensor<1, 3>, 2>
  GasserOgdenHolzapfelMaterial::fibre_directions(const Point<3> &X) const
  {
    const double degrees = langer_line_angle->value(Point<2>(X[0], X[1]));
    AssertThrow(std::isfinite(degrees),
                ExcMessage("Langer line angle is not a number at x = " +
                           std::to_string(X[0]) +
                           " mm, y = " + std::to_string(X[1]) + " mm."));
    const double                theta = degrees * numbers::PI / 180.;
    std::array<Tensor<1, 3>, 2> a;
    for (unsigned int family = 0; family < 2; ++family)
      {
        const double angle = theta + (family == 0 ? fibre_angle : -fibre_angle);
        a[family][0]       = std::cos(angle);
        a[family][1]       = std::sin(angle);
      }
    return a;
  }


  SymmetricTensor<2, 3>
  GasserOgdenHolzapfelMaterial::fibre_stress(
    const Point<3>        &X,
    const Tensor<2, 3>    &F,
    SymmetricTensor<4, 3> *fibre_tangent) const
  {
    const SymmetricTensor<2, 3> b = symmetrize(F * transpose(F));
    SymmetricTensor<2, 3>       tau;
    if (fibre_tangent != nullptr)
      *fibre_tangent = 0;
    for (const Tensor<1, 3> &a0 : fibre_directions(X))
      {
        const Tensor<1, 3> a = F * a0;
        const double       E =
          recruitment * (kappa * trace(b) + (1. - 3. * kappa) * (a * a)) - 1.;
        if (!(E > 0.)) // the family bears tension only
          continue;
        const SymmetricTensor<2, 3> h =
          recruitment *
          (kappa * b + (1. - 3. * kappa) * symmetrize(outer_product(a, a)));
        const double growth = std::exp(k2 * E * E);
        tau += 2. * k1 * E * growth * h;
        if (fibre_tangent != nullptr)
          *fibre_tangent +=
            4. * k1 * (1. + 2. * k2 * E * E) * growth * outer_product(h, h);
      }
    return tau;
  }


  SymmetricTensor<2, 3>
  GasserOgdenHolzapfelMaterial::isochoric_stress(const Point<3>     &X,
                                                 const Tensor<2, 3> &F) const
  {
    return matrix.isochoric_stress(X, F) + fibre_stress(X, F, nullptr);
  }


  void
  GasserOgdenHolzapfelMaterial::isochoric_response(const Point<3>        &X,
                                                   const Tensor<2, 3>    &F,
                                                   SymmetricTensor<2, 3> &tau,
                                                   Tensor<4, 3> &tangent) const
  {
    matrix.isochoric_response(X, F, tau, tangent);
    SymmetricTensor<4, 3>       c;
    const SymmetricTensor<2, 3> tau_f = fibre_stress(X, F, &c);
    tau += tau_f;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int l = 0; l < 3; ++l)
            tangent[i][k][j][l] += c[i][k][j][l] + (i == j ? tau_f[k][l] : 0.);
  }


  double
  GasserOgdenHolzapfelMaterial::energy(const Point<3>     &X,
                                       const Tensor<2, 3> &F) const
  {
    const SymmetricTensor<2, 3> C   = symmetrize(transpose(F) * F);
    double                      psi = matrix.energy(X, F);
    for (const Tensor<1, 3> &a0 : fibre_directions(X))
      {
        const double E = recruitment * (kappa * trace(C) +
                                        (1. - 3. * kappa) * (a0 * (C * a0))) -
                         1.;
        if (E > 0.)
          // k1/(2 k2) (exp(k2 E^2) - 1), whose limit at k2 = 0 is k1/2 E^2
          psi += 0.5 * k1 * (k2 > 0. ? std::expm1(k2 * E * E) / k2 : E * E);
      }
    return psi;
  }


  namespace
  {
    const bool registered = register_material<GasserOgdenHolzapfelMaterial,
                                              GasserOgdenHolzapfelParameters>(
      "Gasser-Ogden-Holzapfel",
      "fibre-reinforced skin: the neo-Hookean matrix of E and nu plus two "
      "dispersed collagen fibre families at +-gamma to Langer's lines, "
      "bearing tension only (finite strain).");
  }
} // namespace ssc
