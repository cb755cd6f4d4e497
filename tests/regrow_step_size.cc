// Newton / Regrow step size. The same quarter-circle run twice, with
// Newton's method limited to 3 iterations and the absolute tolerance of
// 1e-12 (the default until 2026-11-27; with 1e-10, 3 iterations reach it
// at the full Tau) so that a step of the full Tau fails and is halved:
// - false (the thesis's grid): every step first tries Tau, so
//   tau * 2^step_halvings = Tau in every row of statistics.csv;
// - true: step 1 tries Tau; each later step tries the size of the step
//   before if that one was halved, else twice it, at most Tau.
// The test checks these rules on the columns `tau` and `step_halvings`,
// that the time is the sum of the steps, that regrowing needs fewer
// halvings (failed attempts) in all, and that both runs follow the exact
// law of the quarter circle at their own times.

#include "tests.h"

namespace
{
  constexpr double tau_per_h = 0.06;
  constexpr int    level     = 6;
  const double     full_tau  = tau_per_h / (1 << level);

  /** The run with Newton / Regrow step size = @p regrow. */
  std::vector<std::vector<double>>
  run(const bool regrow, std::vector<std::string> &header)
  {
    return Testing::run_willmore(Testing::quarter_circle_level6 + R"(
subsection Time stepping
  set Tau = 0.06*h
  set Inner tau = h^2
  set Number of steps = 8
end
subsection Newton
  set Maximum iterations = 3
  set Absolute tolerance = 1e-12
  set Maximum descent iterations = 1
  set Regrow step size = )" + (regrow ? "true" : "false") +
                                   R"(
end
subsection Output
  set VTU interval = 0
end
)",
                                 header,
                                 regrow ? "regrow" : "scheduled");
  }

  /** The size step @p i first tried: tau * 2^step_halvings. */
  double
  tried(const std::vector<double> &row, const std::vector<std::string> &header)
  {
    return row[Testing::column(header, "tau")] *
           std::pow(2., row[Testing::column(header, "step_halvings")]);
  }

  /** Does every step follow the rule, and is the time their sum? */
  bool
  follows_rule(const std::vector<std::vector<double>> &rows,
               const std::vector<std::string>         &header,
               const bool                              regrow)
  {
    const int tau = Testing::column(header, "tau");
    const int h   = Testing::column(header, "step_halvings");
    double    t   = 0;
    bool      ok  = true;
    for (unsigned int i = 1; i < rows.size(); ++i)
      {
        double expected = full_tau;
        if (regrow && i > 1)
          expected = rows[i - 1][h] > 0 ?
                       rows[i - 1][tau] :
                       std::min(full_tau, 2 * rows[i - 1][tau]);
        t += rows[i][tau];
        ok = ok && std::abs(tried(rows[i], header) / expected - 1) < 1e-12 &&
             std::abs(rows[i][Testing::column(header, "time")] / t - 1) < 1e-9;
      }
    return ok;
  }

  /** Print tau / Tau and the halvings of every step of @p rows. */
  void
  log_steps(const std::vector<std::vector<double>> &rows,
            const std::vector<std::string>         &header)
  {
    for (unsigned int i = 1; i < rows.size(); ++i)
      Testing::log() << "  step " << i << ": tau / Tau = "
                     << rows[i][Testing::column(header, "tau")] / full_tau
                     << ", halvings "
                     << rows[i][Testing::column(header, "step_halvings")]
                     << std::endl;
  }

  double
  total_halvings(const std::vector<std::vector<double>> &rows,
                 const std::vector<std::string>         &header)
  {
    double n = 0;
    for (const auto &row : rows)
      n += row[Testing::column(header, "step_halvings")];
    return n;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string>                 header;
  double                                   halvings[2];
  for (const bool regrow : {false, true})
    {
      const auto rows = run(regrow, header);
      Testing::log() << "Regrow step size = " << (regrow ? "true" : "false")
                     << std::endl;
      log_steps(rows, header);
      Testing::log() << "first attempts and time follow the rule: "
                     << (follows_rule(rows, header, regrow) ? "yes" : "NO")
                     << std::endl;
      halvings[regrow] = total_halvings(rows, header);
      Testing::check_quarter_circle(rows, header, 0.4, 0.02, 0.10);
    }
  Testing::log() << "halvings in all: " << halvings[0] << " (scheduled), "
                 << halvings[1] << " (regrow); fewer with regrow: "
                 << (halvings[1] < halvings[0] ? "yes" : "NO") << std::endl;
}
