#include <algorithm>
#include <cmath>
#include <iomanip>
#include <phasefield/solvers/augmented_lagrangian.h>
#include <phasefield/solvers/rol_trust_region.h>

namespace PhaseField
{
  AugmentedLagrangianObjective::AugmentedLagrangianObjective(
    ConstrainedMinimizationProblem &problem,
    const Vector                   &p,
    const double                    penalty)
    : problem(problem)
    , p(p)
    , penalty(penalty)
    , y(p)
  {}



  double
  AugmentedLagrangianObjective::value(const BlockVector &x)
  {
    Vector c(p), m_inverse_c(p);
    problem.constraint(x, c);
    problem.riesz(c, m_inverse_c);
    return problem.objective(x) - c * p + 0.5 * penalty * (c * m_inverse_c);
  }



  void
  AugmentedLagrangianObjective::gradient(const BlockVector &x, BlockVector &g)
  {
    // Y = -P + lambda M^-1 c, grad l_A = grad f + J^T Y
    Vector c(p);
    problem.constraint(x, c);
    problem.riesz(c, y);
    y.sadd(penalty, -1., p);
    problem.objective_gradient(x, g);
    BlockVector jty(g);
    problem.constraint_jacobian_tvmult(x, y, jty);
    g += jty;
    point = x;
    problem.setup_preconditioner(point, y, penalty);
  }



  void
  AugmentedLagrangianObjective::hessian_vmult(const BlockVector &d,
                                              BlockVector       &hd) const
  {
    // H = f'' + lambda J^T M^-1 J + sum_i Y_i c_i''
    problem.objective_hessian_vmult(point, d, hd);
    Vector jd(p), m_inverse_jd(p);
    problem.constraint_jacobian_vmult(point, d, jd);
    problem.riesz(jd, m_inverse_jd);
    m_inverse_jd *= penalty;
    BlockVector term(hd);
    problem.constraint_jacobian_tvmult(point, m_inverse_jd, term);
    hd += term;
    problem.constraint_hessian_vmult(point, y, d, term);
    hd += term;
  }



  void
  AugmentedLagrangianObjective::precondition(const BlockVector &r,
                                             BlockVector       &z) const
  {
    problem.precondition(r, z);
  }



  double
  AugmentedLagrangianObjective::gradient_norm(const BlockVector &g) const
  {
    return problem.gradient_norm(g);
  }



  void
  AugmentedLagrangianObjective::distribute_constraints(BlockVector &x) const
  {
    problem.distribute_constraints(x);
  }



  namespace
  {
    /** ||C||_L2 = sqrt(c.M^-1 c) of the constraint at @p x; M^-1 c in @p
     * m_inverse_c. */
    double
    constraint_norm(const ConstrainedMinimizationProblem &problem,
                    const BlockVector                    &x,
                    Vector                               &m_inverse_c)
    {
      Vector c(m_inverse_c);
      problem.constraint(x, c);
      problem.riesz(c, m_inverse_c);
      return std::sqrt(std::max(c * m_inverse_c, 0.));
    }
  } // namespace



  AugmentedLagrangianReport
  augmented_lagrangian_minimize(ConstrainedMinimizationProblem   &problem,
                                BlockVector                      &x,
                                Vector                           &p,
                                const AugmentedLagrangianControl &control,
                                const dealii::ConditionalOStream &pcout,
                                const bool                        verbose)
  {
    namespace AL = AugmentedLagrangian;
    AugmentedLagrangianReport report;
    double                    lambda = control.initial_penalty;
    double                    w      = 1 / lambda;
    double                    eta    = std::pow(lambda, -AL::eta_exponent);
    TrustRegionControl        inner  = control.trust_region;
    Vector                    m_inverse_c(p);
    if (verbose)
      inner.progress = &pcout;
    {
      AugmentedLagrangianObjective objective(problem, p, lambda);
      BlockVector                  g(x);
      objective.distribute_constraints(x);
      objective.gradient(x, g);
      report.initial_gradient_norm   = problem.gradient_norm(g);
      report.initial_constraint_norm = constraint_norm(problem, x, m_inverse_c);
    }
    while (report.outer_iterations < control.max_outer_iterations &&
           report.tr_iterations < control.max_total_trust_region_iterations &&
           report.cg_iterations < control.max_total_cg_iterations)
      {
        ++report.outer_iterations;
        inner.gradient_tolerance = std::max(w, control.gradient_tolerance);
        inner.max_iterations =
          std::min(control.trust_region.max_iterations,
                   control.max_total_trust_region_iterations -
                     report.tr_iterations);
        inner.max_total_cg_iterations =
          control.max_total_cg_iterations - report.cg_iterations;
        AugmentedLagrangianObjective objective(problem, p, lambda);
        const TrustRegionReport      tr =
          control.rol_trust_region ?
                 rol_trust_region_minimize(objective, x, inner) :
                 trust_region_minimize(objective, x, inner);
        report.tr_iterations += tr.iterations;
        report.cg_iterations += tr.cg_iterations;
        report.gradient_norm   = tr.gradient_norm;
        report.final_penalty   = lambda;
        report.constraint_norm = constraint_norm(problem, x, m_inverse_c);
        if (verbose)
          pcout << "    AL " << report.outer_iterations
                << ": lambda = " << std::setprecision(3) << lambda
                << "  trust region " << tr.iterations << " (CG "
                << tr.cg_iterations << ")  |grad l_A| = " << tr.gradient_norm
                << "  |C| = " << report.constraint_norm << std::endl;
        if (!tr.converged)
          return report;
        if (report.constraint_norm <= eta)
          {
            if (report.constraint_norm <= control.constraint_tolerance &&
                (tr.gradient_norm <= control.gradient_tolerance ||
                 tr.at_roundoff))
              {
                report.converged = true;
                return report;
              }
            // first-order multiplier update
            p.add(-lambda, m_inverse_c);
            eta /= std::pow(lambda, AL::eta_decay_exponent);
            w /= lambda;
          }
        else
          {
            lambda *= AL::penalty_growth;
            eta = std::pow(lambda, -AL::eta_exponent);
            w   = 1 / lambda;
          }
      }
    return report;
  }
} // namespace PhaseField
