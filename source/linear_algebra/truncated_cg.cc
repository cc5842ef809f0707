#include <cmath>

#include <ssc/linear_algebra/truncated_cg.h>

namespace ssc
{
  namespace
  {
    /// The step tau >= 0 with ||p + tau d||_M = radius, from
    /// ||p||_M^2 = pp, (p, M d) = pd and ||d||_M^2 = dd (pp <= radius^2).
    double
    step_to_boundary(const double pp,
                     const double pd,
                     const double dd,
                     const double radius)
    {
      const double gap = std::max(radius * radius - pp, 0.);
      // the root of dd tau^2 + 2 pd tau - gap = 0 written without
      // cancellation
      const double root = std::sqrt(pd * pd + dd * gap);
      return pd > 0 ? gap / (pd + root) : (root - pd) / dd;
    }
  } // namespace


  TruncatedCGReport
  truncated_cg(
    const TrilinosWrappers::SparseMatrix                       &K,
    const TrilinosWrappers::PreconditionBase                   &P,
    const TrilinosWrappers::MPI::Vector                        &rhs,
    const double                                                radius_in,
    const double                                                tolerance,
    const unsigned int                                          max_iterations,
    const std::function<void(TrilinosWrappers::MPI::Vector &)> &project,
    TrilinosWrappers::MPI::Vector                              &step)
  {
    TruncatedCGReport report;
    // r = K p + g with p = 0, z = P r, d = -z
    TrilinosWrappers::MPI::Vector r(rhs), z(rhs), d(rhs), Kd(rhs);
    r *= -1.;
    project(r);
    step = 0.;
    P.vmult(z, r);
    project(z);
    double rz             = r * z;
    report.final_residual = r.l2_norm();
    if (!(rz > 0.))
      {
        report.preconditioner_indefinite = rz < 0.;
        return report;
      }
    report.gradient_norm = std::sqrt(rz);
    const double radius  = radius_in > 0 ? radius_in : report.gradient_norm;
    d.equ(-1., z);
    // the M-norms: pp = ||p||^2, pd = (p, M d), dd = ||d||^2
    double     pp = 0., pd = 0., dd = rz;
    const auto finish = [&]() {
      // with r = K p + g: m(p) = g.p + p.K p / 2 = (g.p + r.p) / 2, g = -rhs
      report.predicted_decrease = -0.5 * (r * step - rhs * step);
      report.step_norm          = std::sqrt(pp);
      report.final_residual     = r.l2_norm();
      return report;
    };
    while (report.iterations < max_iterations)
      {
        ++report.iterations;
        K.vmult(Kd, d);
        project(Kd);
        const double dKd = d * Kd;
        // non-positive curvature: the model falls without bound along d
        report.negative_curvature = dKd <= 0.;
        const double alpha        = rz / dKd;
        const double pp_next      = pp + 2. * alpha * pd + alpha * alpha * dd;
        if (report.negative_curvature || pp_next >= radius * radius)
          {
            // along d to the boundary
            report.on_boundary = true;
            const double tau   = step_to_boundary(pp, pd, dd, radius);
            step.add(tau, d);
            r.add(tau, Kd);
            pp = radius * radius;
            return finish();
          }
        step.add(alpha, d);
        r.add(alpha, Kd);
        pp = pp_next;
        if (r.l2_norm() <= tolerance)
          return finish();
        P.vmult(z, r);
        project(z);
        const double rz_next = r * z;
        if (!(rz_next > 0.))
          {
            report.preconditioner_indefinite = true;
            return finish();
          }
        const double beta = rz_next / rz;
        rz                = rz_next;
        // recurrences of the M-norms (Conn, Gould and Toint, (7.5.5)-(7.5.7))
        pd = beta * (pd + alpha * dd);
        dd = rz + beta * beta * dd;
        d.sadd(beta, -1., z);
      }
    return finish();
  }
} // namespace ssc
