// The sliding-block check of Coulomb friction on the punch's face
// (Punch/Contact = friction) against its closed form: a stiff block
// pressed with N = 0.1 N by a rigid face as large as its top, then dragged
// sideways by s. Every node carries the same share of the pressure as of
// the stick stiffness (data/sliding_block.prm), so the block
// sticks with F_t = K s, K the sum of the stick stiffnesses, up to
// s* = mu N / K = 1.25 mm, and slides beyond with F_t = mu N = 0.05 N. The
// friction force on the face must also balance the shear reaction of the
// fixed bottom (equilibrium, independent of the friction's bookkeeping),
// and the tie's normal forces must add up to N (each increment is solved
// again until they settle, so also the first).
// Between the two regimes the block slips partially: the drag at its top
// and the bottom's reaction form a couple that the normal forces balance,
// loading the leading edge more (about +-50 % at F_t = mu N), so the
// trailing nodes reach their limit first, as a real sliding block's do.
// An increment abandoned after a pass that updated the normal forces
// (PunchFriction::reject(), called when the load stepping cuts) leaves
// them as the last accepted increment handed them on: accepting the
// converged state again then settles at once.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>

#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/punch_loading.h>
#include <ssc/scenes/quasi_static_driver.h>

#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::Parameters parameters;
  parameters.read(SOURCE_DIR "/data/sliding_block.prm", {});
  dealii::TimerOutput        timer(MPI_COMM_WORLD,
                            dealii::deallog.get_file_stream(),
                            dealii::TimerOutput::never,
                            dealii::TimerOutput::wall_times);
  dealii::ConditionalOStream silent(std::cout, false);
  ssc::MechanicsModel model(parameters, MPI_COMM_WORLD, timer, silent, silent);
  ssc::ElasticSystem &system = model.system();
  ssc::PunchLoading   loading(parameters, system, timer, silent);
  ssc::PunchFriction &friction = *loading.friction();
  ssc::QuasiStaticDriver driver(system, parameters.newton, silent, false);

  const double normal_force = 0.1, mu = 0.5, slide_end = 2.5;
  const double K      = friction.total_stiffness();
  const double s_star = mu * normal_force / K;
  dealii::deallog << std::setprecision(6) << friction.n_nodes()
                  << " nodes under the face, K = " << K
                  << " N/mm, stick limit s* = " << s_star << " mm" << std::endl;
  // load parameter t: pressed to t N for t <= 1, then slid by
  // (t - 1) slide_end at N
  const auto apply = [&](const double t) {
    loading.apply(normal_force * std::min(t, 1.));
    dealii::Tensor<1, 2> offset;
    offset[0] = std::max(t - 1., 0.) * slide_end;
    friction.set_offset(offset);
  };
  std::vector<double> targets = {1.};
  for (unsigned int k = 1; k <= 10; ++k)
    targets.push_back(1. + k / 10.);
  bool   all_within  = true;
  double worst_stick = 0, worst_slip = 0, worst_balance = 0;
  driver.run(
    targets,
    apply,
    0.5,
    ssc::LoadDependence::tangent,
    [&](const unsigned int step) {
      const double              s     = (targets[step] - 1.) * slide_end;
      const ssc::FrictionState &state = friction.accepted_state();
      // the force that drags the punch: against the skin's on it
      const double F_t      = -state.tangential_force[0];
      const double bottom_x = system.reaction(0)[0];
      const double expected = std::min(K * s, mu * normal_force);
      // whole-face stick: K s; gross slip: mu times the normal forces
      if (state.slipping == 0)
        worst_stick =
          std::max(worst_stick, std::abs(F_t - K * s) / (mu * normal_force));
      if (state.sticking == 0)
        worst_slip = std::max(worst_slip,
                              std::abs(F_t - mu * state.normal_force) /
                                (mu * normal_force));
      worst_balance =
        std::max(worst_balance, std::abs(F_t + bottom_x) / (mu * normal_force));
      all_within = all_within && F_t <= mu * state.normal_force * (1 + 1e-9);
      // round-off at s = 0 differs between runs
      const double ratio =
        std::abs(F_t) < 1e-12 ? 0. : F_t / (mu * normal_force);
      dealii::deallog << "s = " << std::setw(4) << s << " mm: F_t/(mu N) "
                      << std::setprecision(4) << ratio << ", closed form "
                      << expected / (mu * normal_force) << "; "
                      << state.sticking << " nodes stick, " << state.slipping
                      << " slip; sum of normal forces " << state.normal_force
                      << " N" << std::setprecision(6) << std::endl;
    });
  dealii::deallog << "stick: |F_t - K s| / (mu N) below 0.005: "
                  << (worst_stick < 5e-3 ? "yes" : "no") << std::endl;
  dealii::deallog << "slip: |F_t - mu N| / (mu N) below 1e-6: "
                  << (worst_slip < 1e-6 ? "yes" : "no") << std::endl;
  dealii::deallog << "F_t never above mu N: " << (all_within ? "yes" : "no")
                  << std::endl;
  {
    // a pass at a state far from the converged one changes the normal
    // forces (the increment is to be solved again); abandoning it must
    // restore them
    const dealii::TrilinosWrappers::MPI::Vector converged =
      system.field().owned_solution();
    dealii::TrilinosWrappers::MPI::Vector far = converged;
    far *= 1.5;
    system.field().set_solution(far);
    const bool unsettled = !system.accept_state();
    system.reject_state();
    system.field().set_solution(converged);
    dealii::deallog << "a pass 50 % beyond the converged state asks for "
                       "another solve: "
                    << (unsettled ? "yes" : "no")
                    << "; after reject_state() the converged state settles "
                       "at once: "
                    << (system.accept_state() ? "yes" : "no") << std::endl;
  }
  dealii::deallog << "friction balances the bottom's shear reaction to "
                     "1e-6 mu N: "
                  << (worst_balance < 1e-6 ? "yes" : "no") << std::endl;
}
