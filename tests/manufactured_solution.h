#ifndef ssc_tests_manufactured_solution_h
#define ssc_tests_manufactured_solution_h

// Manufactured solutions for layered linear elasticity.
//
// A smooth field v(x) with value, gradient and Hessian in closed form; in
// layer k the exact displacement is u = v / E_k. With the same nu in every
// layer the stress sigma(u) = sigma_1(v) (sigma for E = 1) is one smooth
// field, so tractions are continuous across interfaces, and u is continuous
// because v vanishes on every interface. The body force -div sigma_1(v) is
// the same in every layer.

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <memory>
#include <vector>

#include <ssc/mesh/layer_stack.h>

namespace ssc_test
{
  using namespace dealii;

  /// v, grad v (G[i][j] = d_j v_i) and Hessian (H[i][j][k] = d_jk v_i).
  struct Jet
  {
    Tensor<1, 3> value;
    Tensor<2, 3> gradient;
    Tensor<3, 3> hessian;
  };

  class SmoothField
  {
  public:
    virtual ~SmoothField() = default;
    virtual Jet
    jet(const Point<3> &p) const = 0;
  };

  /// v_i = q(z) sin(k . x + c_i), q(z) = prod_j (z - z_j) over interfaces.
  class LayeredTrigField : public SmoothField
  {
  public:
    explicit LayeredTrigField(const std::vector<double> &interfaces)
      : interfaces(interfaces)
    {}

    Jet
    jet(const Point<3> &p) const override
    {
      // q, q', q'' by the product rule over the linear factors
      double q = 1, dq = 0, ddq = 0;
      for (const double zj : interfaces)
        {
          const double f = p[2] - zj;
          ddq            = ddq * f + 2 * dq;
          dq             = dq * f + q;
          q              = q * f;
        }
      const double k[3] = {M_PI, 0.8 * M_PI, 0.6 * M_PI};
      const double c[3] = {0.3, 0.7, 1.1};
      Jet          r;
      for (unsigned int i = 0; i < 3; ++i)
        {
          const double arg = k[0] * p[0] + k[1] * p[1] + k[2] * p[2] + c[i];
          const double S = std::sin(arg), C = std::cos(arg);
          r.value[i] = q * S;
          for (unsigned int j = 0; j < 3; ++j)
            {
              const double dqj = (j == 2 ? dq : 0.);
              r.gradient[i][j] = dqj * S + q * k[j] * C;
              for (unsigned int l = 0; l < 3; ++l)
                {
                  const double dql   = (l == 2 ? dq : 0.);
                  const double ddqj  = (j == 2 && l == 2 ? ddq : 0.);
                  r.hessian[i][j][l] = ddqj * S + dqj * k[l] * C +
                                       dql * k[j] * C - q * k[j] * k[l] * S;
                }
            }
        }
      return r;
    }

  private:
    std::vector<double> interfaces;
  };

  /// Divergence-free v = (d_y psi, -d_x psi, 0), psi = sin(ax) sin(ay) sin(az).
  class DivergenceFreeField : public SmoothField
  {
  public:
    Jet
    jet(const Point<3> &p) const override
    {
      // d^n/dx^n sin(a x) = a^n sin(a x + n pi/2)
      const double a   = M_PI;
      auto         psi = [&](const unsigned int nx,
                     const unsigned int ny,
                     const unsigned int nz) {
        auto d = [a](const unsigned int n, const double x) {
          return std::pow(a, n) * std::sin(a * x + n * M_PI / 2);
        };
        return d(nx, p[0]) * d(ny, p[1]) * d(nz, p[2]);
      };
      // u_0 = psi_(0,1,0), u_1 = -psi_(1,0,0): multi-index of each
      const int    base[2][3] = {{0, 1, 0}, {1, 0, 0}};
      const double sign[2]    = {1., -1.};
      Jet          r;
      for (unsigned int i = 0; i < 2; ++i)
        {
          int n[3]   = {base[i][0], base[i][1], base[i][2]};
          r.value[i] = sign[i] * psi(n[0], n[1], n[2]);
          for (unsigned int j = 0; j < 3; ++j)
            {
              ++n[j];
              r.gradient[i][j] = sign[i] * psi(n[0], n[1], n[2]);
              for (unsigned int l = 0; l < 3; ++l)
                {
                  ++n[l];
                  r.hessian[i][j][l] = sign[i] * psi(n[0], n[1], n[2]);
                  --n[l];
                }
              --n[j];
            }
        }
      return r;
    }
  };

  /// u = v / E(layer at p).
  class ExactDisplacement : public Function<3>
  {
  public:
    ExactDisplacement(std::shared_ptr<const SmoothField> field,
                      const ssc::LayerStack             &layers)
      : Function<3>(3)
      , field(field)
      , layers(layers)
    {}

    double
    value(const Point<3> &p, const unsigned int c) const override
    {
      return field->jet(p).value[c] / modulus(p);
    }

    Tensor<1, 3>
    gradient(const Point<3> &p, const unsigned int c) const override
    {
      return field->jet(p).gradient[c] / modulus(p);
    }

  private:
    double
    modulus(const Point<3> &p) const
    {
      return layers.layer(layers.layer_at(p)).youngs_modulus;
    }

    std::shared_ptr<const SmoothField> field;
    const ssc::LayerStack             &layers;
  };

  /// f = -div sigma_1(v) for Poisson's ratio nu (E = 1).
  class BodyForce : public Function<3>
  {
  public:
    BodyForce(std::shared_ptr<const SmoothField> field, const double nu)
      : Function<3>(3)
      , field(field)
      , lambda(nu / ((1 + nu) * (1 - 2 * nu)))
      , mu(1. / (2 * (1 + nu)))
    {}

    double
    value(const Point<3> &p, const unsigned int i) const override
    {
      const Tensor<3, 3> H = field->jet(p).hessian;
      double             f = 0;
      for (unsigned int k = 0; k < 3; ++k)
        f += lambda * H[k][k][i] + mu * (H[i][k][k] + H[k][i][k]);
      return -f;
    }

  private:
    std::shared_ptr<const SmoothField> field;
    const double                       lambda, mu;
  };
} // namespace ssc_test

#endif
