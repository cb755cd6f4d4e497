// Step control, end time and stationarity (doc/willmore_flow.md, "Step
// control"), on the quarter circle of parameter_files/willmore_flow/
// quarter_circle_h8.prm (r0 = 0.4, eps = 2^-6, Gauss-Lobatto stiffness),
// whose sharp-interface radius is r(t) = (r0^4 + 2t)^(1/4).
//
// 1. Fixed steps of Tau = h^2 to `End time` = 80 h^2 (Number of steps not
//    set): 80 steps, ending at 80 h^2.
// 2. `Step control = adaptive`, `Tolerance` = 1e-4, from Tau = h^2 to the
//    same end time: it must end there exactly, every accepted step's
//    estimate must be within the tolerance, the steps must grow beyond
//    3 h^2, take fewer than half the fixed steps, and reach the fixed
//    steps' L2 error within 5% (the spatial error
//    dominates at h = 2^-8). A controller that does not grow the steps, or
//    grows them beyond its tolerance, fails one of these.
// 3. `Stationary tolerance` = 10 at level 7 with adaptive steps: the run
//    must end after the first step whose relative change of the energy
//    (W here) per unit time, |W(k) - W(k-1)| / (tau W(k)), is below 10,
//    and not before, within its 200 steps. (For the sharp interface
//    W ~ 1 / r and the rate is r'/r = 1 / (2 r^4), 19.5 at r0 = 0.4; at
//    eps = 2h the diffuse W starts above the sharp one and falls faster,
//    so the end time is not compared with the sharp law.)

#include "tests.h"

namespace
{
  const std::string quarter_circle = R"(
set Dimension = 2
subsection Geometry
  set Shape  = quarter circle
  set Radius = 0.4
end
subsection Mesh
  set Coarsest level       = 3
  set Refinement interval  = 5
  set Stiffness quadrature = Gauss-Lobatto
end
subsection Phase field
  set Epsilon = 2^-6
end
subsection Time stepping
  set Tau       = h^2
  set Inner tau = h^2
end
subsection Output
  set VTU interval = 0
end
)";

  /** Whether @p condition holds, as the output says it. */
  std::string
  yes(const bool condition)
  {
    return condition ? "yes" : "NO";
  }

  /** The largest value of column @p name in @p rows after step 0. */
  double
  largest(const std::vector<std::vector<double>> &rows,
          const std::vector<std::string>         &header,
          const std::string                      &name)
  {
    double value = -std::numeric_limits<double>::infinity();
    for (unsigned int i = 1; i < rows.size(); ++i)
      value = std::max(value, rows[i][Testing::column(header, name)]);
    return value;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string>                 header;
  constexpr double                         h       = 1. / 256;
  const std::string                        level_8 = quarter_circle + R"(
subsection Mesh
  set Finest level = 8
end
subsection Time stepping
  set End time = 80*h^2
end
)";
  const auto fixed = Testing::run_willmore(level_8, header, "fixed");
  const auto error = [&](const std::vector<std::vector<double>> &rows) {
    return rows.back()[Testing::column(header, "l2_error")];
  };
  const auto time = [&](const std::vector<std::vector<double>> &rows) {
    return rows.back()[Testing::column(header, "time")];
  };
  Testing::log() << "fixed steps: " << fixed.size() - 1
                 << " steps, end time = 80 h^2: "
                 << yes(std::abs(time(fixed) - 80 * h * h) < 1e-12)
                 << ", L2 error " << error(fixed) << std::endl;

  const auto         adaptive   = Testing::run_willmore(level_8 + R"(
subsection Time stepping
  set Step control = adaptive
  set Tolerance    = 1e-4
end
)",
                                              header,
                                              "adaptive");
  const unsigned int n_adaptive = adaptive.size() - 1;
  Testing::log() << "adaptive steps:" << std::endl
                 << "  end time = 80 h^2: "
                 << yes(std::abs(time(adaptive) - 80 * h * h) < 1e-12)
                 << std::endl
                 << "  fewer than 40 steps: " << yes(n_adaptive < 40)
                 << std::endl
                 << "  estimates within the tolerance: "
                 << yes(largest(adaptive, header, "error_estimate") <= 1e-4)
                 << std::endl
                 << "  largest step above 3 h^2: "
                 << yes(largest(adaptive, header, "tau") > 3 * h * h)
                 << std::endl
                 << "  L2 error within 5% of the fixed steps': "
                 << yes(std::abs(error(adaptive) / error(fixed) - 1) < 0.05)
                 << std::endl;

  const auto stationary = Testing::run_willmore(quarter_circle + R"(
subsection Mesh
  set Finest level = 7
end
subsection Time stepping
  set Step control         = adaptive
  set Tolerance            = 1e-4
  set Number of steps      = 200
  set Stationary tolerance = 10
end
)",
                                                header,
                                                "stationary");
  const auto rate       = [&](const unsigned int k) {
    const int    w   = Testing::column(header, "willmore_energy");
    const double tau = stationary[k][Testing::column(header, "tau")];
    return std::abs(stationary[k][w] - stationary[k - 1][w]) /
           (tau * stationary[k][w]);
  };
  const unsigned int last = stationary.size() - 1;
  Testing::log() << "stationary tolerance 10:" << std::endl
                 << "  ended before step 200: " << yes(last < 200) << std::endl
                 << "  rate of the last step below 10: " << yes(rate(last) < 10)
                 << std::endl
                 << "  rate of the step before at least 10: "
                 << yes(rate(last - 1) >= 10) << std::endl;
}
