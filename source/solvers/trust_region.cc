#include <algorithm>
#include <cmath>
#include <phasefield/core/constants.h>
#include <phasefield/solvers/trust_region.h>

namespace PhaseField
{
  namespace
  {
    /**
     * The t >= 0 with ||s + t d||_B = radius, from sBs = ||s||_B^2,
     * sBd = s.Bd and dBd = ||d||_B^2.
     */
    double
    boundary_step(const double sBs,
                  const double sBd,
                  const double dBd,
                  const double radius)
    {
      const double gap = std::max(radius * radius - sBs, 0.);
      return (-sBd + std::sqrt(sBd * sBd + dBd * gap)) / dBd;
    }

    /** Are the actual and the model decrease both below round-off? */
    bool
    is_noise(const double value,
             const double trial_value,
             const double model_decrease)
    {
      const double noise = Constants::roundoff * (1 + std::abs(value));
      return std::abs(model_decrease) <= noise &&
             std::abs(value - trial_value) <= noise;
    }

    /**
     * rho = actual / predicted decrease; 1 if both are below round-off of
     * @p value, -1 if the trial value or the ratio is not finite.
     */
    double
    reduction_ratio(const double value,
                    const double trial_value,
                    const double model_decrease)
    {
      const double actual = value - trial_value;
      if (!std::isfinite(trial_value))
        return -1;
      if (is_noise(value, trial_value, model_decrease))
        return 1;
      const double rho = actual / model_decrease;
      return std::isfinite(rho) ? rho : -1.;
    }



    /**
     * The line of TrustRegionControl::progress after iteration
     * @p report.iterations, if one is due.
     */
    void
    print_progress(const TrustRegionControl &control,
                   const TrustRegionReport  &report,
                   const double              radius)
    {
      if (control.progress == nullptr ||
          report.iterations % TrustRegion::progress_interval != 0)
        return;
      *control.progress << "      trust region " << report.iterations
                        << ": |grad| = " << report.gradient_norm
                        << "  radius = " << radius << "  (CG "
                        << report.cg_iterations << " so far)" << std::endl;
    }
  } // namespace



  TruncatedCGResult
  truncated_cg(const TrustRegionObjective &objective,
               const BlockVector          &g,
               const double                radius,
               const double                tolerance,
               const unsigned int          max_iterations,
               BlockVector                &s)
  {
    TruncatedCGResult result;
    s = 0;
    BlockVector r(g), z(g), d(g), hd(g);
    objective.precondition(r, z);
    d.equ(-1., z);
    double rz = r * z;
    // the B norms of s and d and their B product (Conn-Gould-Toint 7.5.1)
    double sBs = 0, sBd = 0, dBd = rz;
    while (result.iterations < max_iterations)
      {
        ++result.iterations;
        objective.hessian_vmult(d, hd);
        const double curvature = d * hd;
        const double alpha     = curvature > 0 ? rz / curvature : 0.;
        const double sBs_next  = sBs + 2 * alpha * sBd + alpha * alpha * dBd;
        if (curvature <= 0 || sBs_next >= radius * radius)
          {
            // negative curvature or outside: go to the boundary along d
            const double t = boundary_step(sBs, sBd, dBd, radius);
            s.add(t, d);
            r.add(t, hd);
            result.on_boundary = true;
            sBs                = radius * radius;
            break;
          }
        s.add(alpha, d);
        r.add(alpha, hd);
        sBs = sBs_next;
        if (objective.gradient_norm(r) <= tolerance)
          break;
        objective.precondition(r, z);
        const double rz_next = r * z;
        const double beta    = rz_next / rz;
        rz                   = rz_next;
        sBd                  = beta * (sBd + alpha * dBd);
        dBd                  = rz + beta * beta * dBd;
        d.sadd(beta, -1., z);
      }
    // m(s) = g.s + s.Hs/2 = (g.s + r.s)/2 with r = g + Hs
    result.model_decrease = -0.5 * (g * s + r * s);
    result.step_norm      = std::sqrt(sBs);
    return result;
  }



  TrustRegionReport
  trust_region_minimize(TrustRegionObjective     &objective,
                        BlockVector              &x,
                        const TrustRegionControl &control)
  {
    TrustRegionReport report;
    objective.distribute_constraints(x);
    double      value = objective.value(x);
    BlockVector g(x), s(x), trial(x);
    objective.gradient(x, g);
    report.gradient_norm = objective.gradient_norm(g);
    double radius        = control.initial_radius;
    if (!(radius > 0))
      {
        objective.precondition(g, s);
        radius = std::sqrt(std::abs(g * s));
      }
    const double initial_radius = radius;
    while (!(report.gradient_norm <= control.gradient_tolerance))
      {
        if (report.iterations == control.max_iterations ||
            report.cg_iterations >= control.max_total_cg_iterations ||
            radius < TrustRegion::min_radius * initial_radius ||
            !std::isfinite(value) || !std::isfinite(report.gradient_norm))
          {
            report.radius = radius;
            return report;
          }
        ++report.iterations;
        const double tolerance =
          std::min(TrustRegion::cg_forcing, std::sqrt(report.gradient_norm)) *
          report.gradient_norm;
        const TruncatedCGResult step =
          truncated_cg(objective,
                       g,
                       radius,
                       tolerance,
                       std::min(control.max_cg_iterations,
                                control.max_total_cg_iterations -
                                  report.cg_iterations),
                       s);
        report.cg_iterations += step.iterations;
        trial = x;
        trial += s;
        objective.distribute_constraints(trial);
        const double trial_value = objective.value(trial);
        const double rho =
          reduction_ratio(value, trial_value, step.model_decrease);
        if (rho < TrustRegion::shrink_ratio)
          radius = TrustRegion::shrink * step.step_norm;
        else if (rho > TrustRegion::grow_ratio && step.on_boundary)
          radius = std::min(TrustRegion::grow * radius,
                            TrustRegion::max_radius_factor * initial_radius);
        if (rho > TrustRegion::accept_ratio)
          {
            const double previous_norm = report.gradient_norm;
            const double old_value     = value;
            x                          = trial;
            value                      = trial_value;
            objective.gradient(x, g);
            report.gradient_norm = objective.gradient_norm(g);
            // round-off: no measurable decrease and the gradient stagnates
            if (is_noise(old_value, trial_value, step.model_decrease) &&
                report.gradient_norm > TrustRegion::stagnation * previous_norm)
              {
                report.at_roundoff = true;
                break;
              }
          }
        print_progress(control, report, radius);
      }
    report.converged = true;
    report.radius    = radius;
    return report;
  }
} // namespace PhaseField
