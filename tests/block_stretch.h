#ifndef ssc_tests_block_stretch_h
#define ssc_tests_block_stretch_h

// The homogeneous stretch tests' loading: a 2 x 2 x 2 mm block on symmetry
// rollers, one or two faces moved, solved by Newton's method with load
// steps.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>

#include <memory>
#include <vector>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/nonlinear/elastic_problem.h>
#include <ssc/nonlinear/load_stepping.h>
#include <ssc/nonlinear/newton_solver.h>

/// Sets up @p elasticity (dofs distributed) on the block x, y in [-1, 1],
/// z in [-2, 0] with rollers on x = -1, y = -1 and the bottom, moves the
/// face x = 1 (and the face y = 1 if @p equibiaxial) to the stretch
/// @p lambda in load increments starting at @p increment mm, and returns
/// the load path's report. The conditions are numbered for
/// ElasticSystem::reaction(): 1 the face x = 1, 4 the face y = 1.
inline ssc::LoadPathReport
stretch_block(ssc::ElasticSystem          &elasticity,
              const ssc::NewtonParameters &newton_parameters,
              dealii::ConditionalOStream  &pcout,
              const double                 lambda,
              const bool                   equibiaxial,
              double                       increment)
{
  using namespace dealii;
  const auto zero = std::make_shared<Functions::ZeroFunction<3>>(3);
  // unit value: the faces move by 1 mm
  const auto move_x = std::make_shared<Functions::ConstantFunction<3>>(
    std::vector<double>{1., 0., 0.});
  const auto move_y = std::make_shared<Functions::ConstantFunction<3>>(
    std::vector<double>{0., 1., 0.});
  ComponentMask x(3, false), y(3, false), z(3, false);
  x.set(0, true);
  y.set(1, true);
  z.set(2, true);
  std::vector<ssc::DirichletCondition> conditions = {
    {ssc::BoundaryId::x_min, x, zero, {}},
    {ssc::BoundaryId::x_max, x, move_x, {}},
    {ssc::BoundaryId::y_min, y, zero, {}},
    {ssc::BoundaryId::bottom, z, zero, {}}};
  if (equibiaxial)
    conditions.push_back({ssc::BoundaryId::y_max, y, move_y, {}});
  elasticity.setup(conditions);
  ssc::ElasticProblem problem(elasticity);
  ssc::NewtonSolver   newton(problem, newton_parameters, pcout, false);
  ssc::LoadStepper    stepper(newton);
  const double        target = 2. * (lambda - 1.); // length 2 mm
  return stepper.follow(
    0.,
    std::abs(target),
    increment,
    [&](const double load) {
      elasticity.constraints().set_dirichlet_scale(target > 0 ? load : -load);
    },
    ssc::LoadDependence::right_hand_side);
}

#endif
