#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <limits>

#include <ssc/base/round_robin.h>
#include <ssc/identification/layer_moduli_fit.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>

namespace ssc
{
  using namespace dealii;

  namespace
  {
    /// Step of the log-moduli for the finite-difference sensitivities.
    constexpr double log_step = 1e-3;

    /// A response as the four numbers the ranks exchange (stiffness, the
    /// strains per newton), and back.
    void
    write(const ProbeResponse &response, double *out)
    {
      out[0] = response.stiffness;
      for (unsigned int i = 0; i < 3; ++i)
        out[i + 1] = response.strains_per_newton[i];
    }

    ProbeResponse
    read(const double *in)
    {
      ProbeResponse response;
      response.stiffness = in[0];
      for (unsigned int i = 0; i < 3; ++i)
        response.strains_per_newton[i] = in[i + 1];
      return response;
    }

    /// The forward responses of every trial at one set of moduli: the
    /// unperturbed one, then (with sensitivities) skin and fat perturbed.
    struct Responses
    {
      std::vector<std::array<ProbeResponse, 3>> per_trial;
    };

    /**
     * The least-squares problem in Eigen's functor form: unknowns x, the
     * logs of the fitted moduli over their initial values; residuals as
     * LayerModuliFit describes. The last forward responses are kept, so
     * the Jacobian at the point just evaluated costs only the perturbed
     * solves.
     */
    class LeastSquaresProblem
    {
    public:
      LeastSquaresProblem(const ProbeForwardModel             &model,
                          const std::vector<IndentationTrial> &trials,
                          const std::array<double, 3>         &initial,
                          const std::array<bool, 3>           &fitted_layers,
                          const std::array<bool, 4>           &fitted_data,
                          const MPI_Comm                       communicator)
        : model(model)
        , trials(trials)
        , initial(initial)
        , fitted_data(fitted_data)
        , communicator(communicator)
      {
        for (unsigned int l = 0; l < 3; ++l)
          if (fitted_layers[l])
            unknowns.push_back(l);
        for (unsigned int i = 0; i < 3; ++i)
          {
            double sum = 0;
            for (const auto &trial : trials)
              sum += trial.layer_strains()[i];
            mean_strain[i] = sum / trials.size();
            AssertThrow(!fitted_data[i + 1] || mean_strain[i] > 0,
                        ExcMessage("The trials' mean measured " +
                                   std::string(trial_layer_names[i]) +
                                   " strain is not positive: it cannot be "
                                   "fitted (remove it from Identification/"
                                   "Fitted data)."));
          }
        for (const bool on : fitted_data)
          n_per_trial += on;
      }

      int
      inputs() const
      {
        return unknowns.size();
      }

      int
      values() const
      {
        return trials.size() * n_per_trial;
      }

      std::array<double, 3>
      moduli(const Eigen::VectorXd &x) const
      {
        std::array<double, 3> E = initial;
        for (unsigned int k = 0; k < unknowns.size(); ++k)
          E[unknowns[k]] *= std::exp(x[k]);
        return E;
      }

      int
      operator()(const Eigen::VectorXd &x, Eigen::VectorXd &residuals) const
      {
        const Responses &r = responses(x, false);
        residuals.resize(values());
        unsigned int row = 0;
        for (unsigned int t = 0; t < trials.size(); ++t)
          {
            const ProbeResponse    &response = r.per_trial[t][0];
            const IndentationTrial &trial    = trials[t];
            if (fitted_data[0])
              residuals[row++] =
                std::log(response.stiffness / trial.surface_stiffness);
            for (unsigned int i = 0; i < 3; ++i)
              if (fitted_data[i + 1])
                residuals[row++] =
                  (trial.max_force * response.strains_per_newton[i] -
                   trial.layer_strains()[i]) /
                  mean_strain[i];
          }
        return 0;
      }

      int
      df(const Eigen::VectorXd &x, Eigen::MatrixXd &jacobian) const
      {
        const Responses &r = responses(x, true);
        jacobian.resize(values(), inputs());
        unsigned int row = 0;
        for (unsigned int t = 0; t < trials.size(); ++t)
          {
            const auto &trial_responses = r.per_trial[t];
            // log-derivatives by the skin's and fat's modulus, the
            // muscle's from homogeneity
            const auto log_derivatives = [&](const auto  &quantity,
                                             const double degree) {
              std::array<double, 3> d;
              for (unsigned int l = 0; l < 2; ++l)
                d[l] = std::log(quantity(trial_responses[l + 1]) /
                                quantity(trial_responses[0])) /
                       log_step;
              d[2] = degree - d[0] - d[1];
              return d;
            };
            const auto fill = [&](const std::array<double, 3> &d,
                                  const double                 factor) {
              for (unsigned int k = 0; k < unknowns.size(); ++k)
                jacobian(row, k) = factor * d[unknowns[k]];
              ++row;
            };
            if (fitted_data[0])
              fill(log_derivatives(
                     [](const ProbeResponse &p) { return p.stiffness; }, 1.),
                   1.);
            for (unsigned int i = 0; i < 3; ++i)
              if (fitted_data[i + 1])
                {
                  const double strain =
                    trials[t].max_force *
                    trial_responses[0].strains_per_newton[i];
                  fill(log_derivatives(
                         [i](const ProbeResponse &p) {
                           return p.strains_per_newton[i];
                         },
                         -1.),
                       strain / mean_strain[i]);
                }
          }
        return 0;
      }

      unsigned int
      forward_solves() const
      {
        return n_solves;
      }

    private:
      /// The responses at @p x (with the perturbed ones if
      /// @p sensitivities), each rank solving every n-th trial.
      const Responses &
      responses(const Eigen::VectorXd &x, const bool sensitivities) const
      {
        const bool same_point =
          cached_x.size() == x.size() && (cached_x - x).norm() == 0;
        if (same_point && (cached_sensitivities || !sensitivities))
          return cached;
        const unsigned int n_cases = sensitivities ? 3 : 1;
        const unsigned int first   = same_point ? 1 : 0;
        const auto         E       = moduli(x);
        const auto         values =
          compute_round_robin(trials.size(),
                              3 * 4,
                              communicator,
                              [&](const unsigned int t, double *out) {
                                for (unsigned int c = first; c < n_cases; ++c)
                                  {
                                    auto perturbed = E;
                                    if (c > 0)
                                      perturbed[c - 1] *= std::exp(log_step);
                                    write(model.solve(trials[t], perturbed),
                                          out + 4 * c);
                                  }
                              });
        n_solves += trials.size() * (n_cases - first);
        if (!same_point)
          cached.per_trial.assign(trials.size(), {});
        for (unsigned int t = 0; t < trials.size(); ++t)
          for (unsigned int c = first; c < n_cases; ++c)
            cached.per_trial[t][c] = read(&values[(t * 3 + c) * 4]);
        cached_x             = x;
        cached_sensitivities = sensitivities;
        return cached;
      }

      const ProbeForwardModel             &model;
      const std::vector<IndentationTrial> &trials;
      const std::array<double, 3>          initial;
      const std::array<bool, 4>            fitted_data;
      const MPI_Comm                       communicator;
      std::vector<unsigned int>            unknowns;
      std::array<double, 3>                mean_strain{};
      unsigned int                         n_per_trial = 0;

      mutable Eigen::VectorXd cached_x;
      mutable bool            cached_sensitivities = false;
      mutable Responses       cached;
      mutable unsigned int    n_solves = 0;
    };


    std::string
    stopping_reason(const Eigen::LevenbergMarquardtSpace::Status status)
    {
      using namespace Eigen::LevenbergMarquardtSpace;
      switch (status)
        {
          case RelativeReductionTooSmall:
            return "the sum of squares changes by less than the tolerance";
          case RelativeErrorTooSmall:
            return "the moduli change by less than the tolerance";
          case RelativeErrorAndReductionTooSmall:
            return "the moduli and the sum of squares change by less than "
                   "the tolerance";
          case CosinusTooSmall:
            return "the residuals are orthogonal to the sensitivities";
          case TooManyFunctionEvaluation:
            return "Identification/Maximum iterations reached";
          case FtolTooSmall:
          case XtolTooSmall:
          case GtolTooSmall:
            return "no further improvement possible at machine precision";
          default:
            return "stopped (status " + std::to_string(int(status)) + ")";
        }
    }
  } // namespace


  LayerModuliFit::LayerModuliFit(const ProbeForwardModel        &model,
                                 const IdentificationParameters &parameters,
                                 const MPI_Comm mpi_communicator)
    : model(model)
    , parameters(parameters)
    , mpi_communicator(mpi_communicator)
  {}


  ModuliFit
  LayerModuliFit::fit(const std::vector<IndentationTrial> &trials,
                      const std::array<double, 3>         &initial,
                      ConditionalOStream                  &pcout) const
  {
    const auto          fitted_layers = parameters.fitted_layers();
    LeastSquaresProblem problem(model,
                                trials,
                                initial,
                                fitted_layers,
                                parameters.fitted_measurements(),
                                mpi_communicator);
    AssertThrow(problem.values() >= problem.inputs(),
                ExcMessage(
                  "Identification: " + std::to_string(problem.values()) +
                  " measurements cannot determine " +
                  std::to_string(problem.inputs()) + " moduli."));
    Eigen::LevenbergMarquardt<LeastSquaresProblem> lm(problem);
    lm.parameters.ftol   = parameters.tolerance;
    lm.parameters.xtol   = parameters.tolerance;
    lm.parameters.maxfev = parameters.maximum_iterations;
    // first steps of at most a factor e in the moduli
    lm.parameters.factor   = 1.;
    Eigen::VectorXd x      = Eigen::VectorXd::Zero(problem.inputs());
    auto            status = lm.minimizeInit(x);
    AssertThrow(status !=
                  Eigen::LevenbergMarquardtSpace::ImproperInputParameters,
                ExcMessage("Identification: improper input to the fit."));
    const auto print_moduli = [&](const Eigen::VectorXd &at) {
      const auto E = problem.moduli(at);
      pcout << std::setprecision(4) << "skin " << E[0] << ", fat " << E[1]
            << ", muscle " << E[2] << " MPa";
    };
    do
      {
        status = lm.minimizeOneStep(x);
        pcout << "  iteration " << lm.iter - 1 << ": ";
        print_moduli(x);
        pcout << ", rms residual " << std::setprecision(4)
              << lm.fnorm / std::sqrt(double(problem.values())) << std::endl;
      }
    while (status == Eigen::LevenbergMarquardtSpace::Running);

    ModuliFit result;
    result.moduli          = problem.moduli(x);
    result.iterations      = lm.iter - 1;
    result.rms_residual    = lm.fnorm / std::sqrt(double(problem.values()));
    result.converged       = status > 0 && status < 5;
    result.stopping_reason = stopping_reason(status);

    // the covariance of the log-moduli at the fit: s^2 (J^T J)^-1
    Eigen::MatrixXd jacobian;
    problem.df(x, jacobian);
    result.forward_solves          = problem.forward_solves();
    const int             dof      = problem.values() - problem.inputs();
    const double          nan      = std::numeric_limits<double>::quiet_NaN();
    const double          variance = dof > 0 ? lm.fnorm * lm.fnorm / dof : nan;
    const Eigen::MatrixXd cov =
      variance *
      (jacobian.transpose() * jacobian)
        .ldlt()
        .solve(Eigen::MatrixXd::Identity(problem.inputs(), problem.inputs()));
    unsigned int k = 0;
    for (unsigned int l = 0; l < 3; ++l)
      if (fitted_layers[l])
        {
          const double half_width = 1.959964 * std::sqrt(cov(k, k));
          result.lower[l]         = result.moduli[l] * std::exp(-half_width);
          result.upper[l]         = result.moduli[l] * std::exp(half_width);
          ++k;
        }
      else
        result.lower[l] = result.upper[l] = result.moduli[l];
    return result;
  }


  std::vector<TrialPrediction>
  LayerModuliFit::predict(const std::vector<IndentationTrial> &trials,
                          const std::array<double, 3>         &moduli) const
  {
    const auto values =
      compute_round_robin(trials.size(),
                          4,
                          mpi_communicator,
                          [&](const unsigned int t, double *out) {
                            write(model.solve(trials[t], moduli), out);
                          });
    std::vector<TrialPrediction> predictions(trials.size());
    for (unsigned int t = 0; t < trials.size(); ++t)
      {
        const ProbeResponse response = read(&values[4 * t]);
        predictions[t].stiffness     = response.stiffness;
        for (unsigned int i = 0; i < 3; ++i)
          predictions[t].layer_strains[i] =
            trials[t].max_force * response.strains_per_newton[i];
      }
    return predictions;
  }
} // namespace ssc
