#ifndef ssc_tests_tangent_check_h
#define ssc_tests_tangent_check_h

// The finite-difference check of the Newton tangent shared by the tangent
// tests.

#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <ssc/mechanics/elastic_system.h>

/**
 * Largest |K_ij - dr_i/du_j| and largest |K_ij| over the columns j = 0,
 * stride, 2 stride, ...: K the tangent assembled at @p u, dr/du the central
 * difference (step @p h) of the assembled residual. Leaves the solution at
 * u - h e_j of the last column.
 */
inline std::pair<double, double>
tangent_error(ssc::ElasticSystem                          &elasticity,
              const dealii::TrilinosWrappers::MPI::Vector &u,
              const double                                 h,
              const unsigned int                           stride)
{
  using namespace dealii;
  elasticity.field().set_solution(u);
  elasticity.assemble(true);
  const auto &K             = elasticity.tangent_system().linearised().tangent;
  double      largest_error = 0, largest_entry = 0;
  for (unsigned int j = 0; j < u.size(); j += stride)
    {
      TrilinosWrappers::MPI::Vector plus(u), minus(u);
      plus[j] += h;
      minus[j] -= h;
      plus.compress(VectorOperation::add);
      minus.compress(VectorOperation::add);
      elasticity.field().set_solution(plus);
      elasticity.assemble(false);
      TrilinosWrappers::MPI::Vector r_plus(
        elasticity.tangent_system().linearised().rhs);
      elasticity.field().set_solution(minus);
      elasticity.assemble(false);
      TrilinosWrappers::MPI::Vector r_minus(
        elasticity.tangent_system().linearised().rhs);
      for (unsigned int i = 0; i < u.size(); ++i)
        {
          // system_rhs = -r, so dr/du_j = -(rhs+ - rhs-) / 2h
          const double difference = -(r_plus[i] - r_minus[i]) / (2 * h);
          largest_error =
            std::max(largest_error, std::abs(K.el(i, j) - difference));
          largest_entry = std::max(largest_entry, std::abs(K.el(i, j)));
        }
    }
  return {largest_error, largest_entry};
}

#endif
