#include <deal.II/base/exceptions.h>

#include <numeric>
#include <sstream>

#include <ssc/materials/prony_series.h>

namespace ssc
{
  using namespace dealii;


  double
  PronySeries::long_term_fraction() const
  {
    return 1. -
           std::accumulate(relative_moduli.begin(), relative_moduli.end(), 0.);
  }


  void
  PronySeries::check(const std::string &path) const
  {
    AssertThrow(relative_moduli.size() == relaxation_times.size(),
                ExcMessage(path + "Relative moduli has " +
                           std::to_string(relative_moduli.size()) +
                           " entries and " + path + "Relaxation times " +
                           std::to_string(relaxation_times.size()) +
                           ": one relaxation time per Prony term."));
    for (unsigned int i = 0; i < size(); ++i)
      {
        std::ostringstream g, tau;
        g << relative_moduli[i];
        tau << relaxation_times[i];
        AssertThrow(relative_moduli[i] > 0. && relative_moduli[i] < 1.,
                    ExcMessage(path + "Relative moduli: entry " +
                               std::to_string(i + 1) + " = " + g.str() +
                               " is outside (0, 1): each term relaxes a "
                               "positive fraction of the instantaneous "
                               "shear modulus."));
        AssertThrow(relaxation_times[i] > 0.,
                    ExcMessage(path + "Relaxation times: entry " +
                               std::to_string(i + 1) + " = " + tau.str() +
                               " s is not positive."));
      }
    std::ostringstream sum;
    sum << 1. - long_term_fraction();
    AssertThrow(long_term_fraction() > 0.,
                ExcMessage(path + "Relative moduli sum to " + sum.str() +
                           ", not below 1: the layer would relax to no "
                           "shear stiffness at all."));
  }
} // namespace ssc
