#include <deal.II/base/exceptions.h>

#include <cmath>

#include <ssc/materials/viscoelastic_material.h>

namespace ssc
{
  ViscoelasticMaterial::ViscoelasticMaterial(
    std::unique_ptr<const Material> inner_law,
    PronySeries                     prony)
    : Material(inner_law->moduli(), inner_law->volumetric().form)
    , inner(std::move(inner_law))
    , series(std::move(prony))
  {
    series.check("Viscoelasticity/");
    AssertThrow(inner->n_history_variables() == 0,
                ExcMessage("A visco-elastic layer needs an elastic inner "
                           "law."));
  }


  std::pair<double, SymmetricTensor<2, 3>>
  ViscoelasticMaterial::update_history(const Tensor<2, 3>          &F,
                                       const SymmetricTensor<2, 3> &tau_0,
                                       MaterialPointHistory &history) const
  {
    AssertDimension(history.committed.size(), n_history_variables());
    AssertDimension(history.trial.size(), n_history_variables());
    const auto read = [](const ArrayView<const double> &values,
                         const unsigned int             block) {
      SymmetricTensor<2, 3> S;
      for (unsigned int c = 0; c < 6; ++c)
        S.access_raw_entry(c) = values[6 * block + c];
      return S;
    };
    const auto write = [&](const SymmetricTensor<2, 3> &S,
                           const unsigned int           block) {
      for (unsigned int c = 0; c < 6; ++c)
        history.trial[6 * block + c] = S.access_raw_entry(c);
    };
    const Tensor<2, 3>          F_inv = invert(F);
    const SymmetricTensor<2, 3> S_0 =
      symmetrize(F_inv * Tensor<2, 3>(tau_0) * transpose(F_inv));
    const SymmetricTensor<2, 3> S_0_old = read(history.committed, 0);
    write(S_0, 0);
    double                k = series.long_term_fraction();
    SymmetricTensor<2, 3> S_h;
    for (unsigned int i = 0; i < series.size(); ++i)
      {
        const double x = history.time_step / series.relaxation_times[i];
        const double e = std::exp(-x);
        // (1 - e^{-x}) / x, its series near 0 against cancellation
        const double c = x > 1e-8 ? -std::expm1(-x) / x : 1. - 0.5 * x;
        const SymmetricTensor<2, 3> H_old = read(history.committed, 1 + i);
        write(e * H_old + c * (S_0 - S_0_old), 1 + i);
        const double g = series.relative_moduli[i];
        k += g * c;
        S_h += g * (e * H_old - c * S_0_old);
      }
    return {k, symmetrize(F * Tensor<2, 3>(S_h) * transpose(F))};
  }


  void
  ViscoelasticMaterial::isochoric_response_in_step(
    const Point<3>        &X,
    const Tensor<2, 3>    &F,
    MaterialPointHistory  &history,
    SymmetricTensor<2, 3> &tau,
    Tensor<4, 3>          &tangent) const
  {
    inner->isochoric_response(X, F, tau, tangent);
    const auto [k, tau_h] = update_history(F, tau, history);
    tau                   = k * tau + tau_h;
    tangent *= k;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int k_ = 0; k_ < 3; ++k_)
        for (unsigned int l = 0; l < 3; ++l)
          tangent[i][k_][i][l] += tau_h[k_][l];
  }


  SymmetricTensor<2, 3>
  ViscoelasticMaterial::isochoric_stress_in_step(
    const Point<3>       &X,
    const Tensor<2, 3>   &F,
    MaterialPointHistory &history) const
  {
    const SymmetricTensor<2, 3> tau_0 = inner->isochoric_stress(X, F);
    const auto [k, tau_h]             = update_history(F, tau_0, history);
    return k * tau_0 + tau_h;
  }
} // namespace ssc
