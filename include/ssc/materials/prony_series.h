#ifndef ssc_materials_prony_series_h
#define ssc_materials_prony_series_h

#include <string>
#include <vector>

namespace ssc
{
  /**
   * A deviatoric Prony series: the relaxation function of the isochoric
   * stress g(t) = g_inf + sum_i g_i exp(-t / tau_i), g_inf = 1 - sum_i g_i,
   * relative to the instantaneous response (the convention of Abaqus and
   * CalculiX's *VISCOELASTIC, and of a relaxed fraction alpha = g_1 as in
   * Sims et al. 2010).
   */
  struct PronySeries
  {
    /// g_i, each in (0, 1), their sum below 1.
    std::vector<double> relative_moduli;
    /// tau_i (s), each positive.
    std::vector<double> relaxation_times;

    bool
    empty() const
    {
      return relative_moduli.empty();
    }

    unsigned int
    size() const
    {
      return relative_moduli.size();
    }

    /// g_inf = 1 - sum_i g_i: the long-term over the instantaneous shear
    /// modulus.
    double
    long_term_fraction() const;

    /// Throws, naming the entries under @p path, unless the two lists have
    /// the same length, every g_i lies in (0, 1) with their sum below 1 and
    /// every tau_i is positive.
    void
    check(const std::string &path) const;
  };
} // namespace ssc

#endif
