// Small replacement of deal.II's tests.h (which deal.II does not install):
// every test writes what it checks into the file "output", which the test
// harness compares with the .output file using numdiff.
#ifndef phasefield_tests_tests_h
#define phasefield_tests_tests_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <phasefield/core/parameters.h>
#include <phasefield/problems/contour_problem.h>
#include <phasefield/problems/restoration_parameters.h>
#include <phasefield/problems/restoration_problem.h>
#include <phasefield/problems/willmore_problem.h>
#include <sstream>
#include <string>
#include <vector>

namespace Testing
{
  /** "< tol" or "TOO LARGE: tol (value)" for a relative error. */
  inline std::string
  below(const double error, const double tolerance)
  {
    std::ostringstream text;
    text << (error < tolerance ? "< " : "TOO LARGE: ") << tolerance;
    if (error >= tolerance)
      text << " (" << error << ")";
    return text.str();
  }

  /** The file "output" on rank 0, a null stream elsewhere. */
  inline std::ostream &
  log()
  {
    static std::ofstream null_stream;
    static std::ofstream file;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return null_stream;
    if (!file.is_open())
      {
        file.open("output");
        file << std::setprecision(6);
      }
    return file;
  }

  /** Read a CSV file into a header and rows of numbers. */
  inline std::vector<std::vector<double>>
  read_csv(const std::string &filename, std::vector<std::string> &header)
  {
    std::ifstream                    in(filename);
    std::string                      line;
    std::vector<std::vector<double>> rows;
    header.clear();
    if (std::getline(in, line))
      {
        std::stringstream ss(line);
        std::string       cell;
        while (std::getline(ss, cell, ','))
          header.push_back(cell);
      }
    while (std::getline(in, line))
      {
        std::stringstream   ss(line);
        std::string         cell;
        std::vector<double> row;
        while (std::getline(ss, cell, ','))
          row.push_back(std::stod(cell));
        rows.push_back(row);
      }
    return rows;
  }

  /** Index of @p column in @p header (-1 if absent). */
  inline int
  column(const std::vector<std::string> &header, const std::string &column)
  {
    for (unsigned int i = 0; i < header.size(); ++i)
      if (header[i] == column)
        return i;
    return -1;
  }
} // namespace Testing


namespace Testing
{
  /**
   * Run willmore_flow on the parameters in @p prm_text (the test's output
   * directory is @p directory) and return the rows of statistics.csv.
   */
  inline std::vector<std::vector<double>>
  run_willmore(const std::string        &prm_text,
               std::vector<std::string> &header,
               const std::string        &directory = "results")
  {
    dealii::ParameterHandler prm;
    PhaseField::WillmoreFlowParameters::declare_parameters(prm);
    prm.parse_input_from_string(prm_text +
                                "\nset Output directory = " + directory + "\n");
    PhaseField::WillmoreFlowParameters parameters;
    parameters.parse_parameters(prm);
    if (parameters.dimension == 2)
      PhaseField::WillmoreProblem<2>(parameters, parameters.constraints).run();
    else
      PhaseField::WillmoreProblem<3>(parameters, parameters.constraints).run();
    return read_csv(directory + "/statistics.csv", header);
  }

  /**
   * Run shape_from_contour on the parameters in @p prm_text (output
   * directory @p directory) and return the rows of statistics.csv.
   */
  inline std::vector<std::vector<double>>
  run_contour(const std::string        &prm_text,
              std::vector<std::string> &header,
              const std::string        &directory = "results")
  {
    dealii::ParameterHandler prm;
    PhaseField::ContourParameters::declare_parameters(prm);
    prm.parse_input_from_string(prm_text +
                                "\nset Output directory = " + directory + "\n");
    PhaseField::ContourParameters parameters;
    parameters.parse_parameters(prm);
    if (parameters.willmore.dimension == 2)
      PhaseField::ContourProblem<2>(parameters).run();
    else
      PhaseField::ContourProblem<3>(parameters).run();
    return read_csv(directory + "/statistics.csv", header);
  }

  /** The statistics.csv columns that the program tests compare. */
  inline const std::vector<std::string> &
  checked_columns()
  {
    static const std::vector<std::string> columns = {"step",
                                                     "newton_iterations",
                                                     "willmore_energy",
                                                     "area_energy",
                                                     "inside_measure",
                                                     "l2_error"};
    return columns;
  }

  /**
   * Significant digits of the values in statistics.csv (StatisticsFile),
   * all of which the tables of the tests print: the tolerances of numdiff
   * are set per test in tests/<name>.numdiff, not by rounding.
   */
  constexpr int statistics_digits = 10;

  /** Print the named columns of @p rows with all digits of the file. */
  inline void
  print_columns(const std::vector<std::vector<double>> &rows,
                const std::vector<std::string>         &header,
                const std::vector<std::string>         &columns)
  {
    for (const auto &c : columns)
      log() << c << ' ';
    log() << '\n';
    const auto precision = log().precision(statistics_digits);
    for (const auto &row : rows)
      {
        for (const auto &c : columns)
          log() << row[column(header, c)] << ' ';
        log() << '\n';
      }
    log().precision(precision);
  }
} // namespace Testing


namespace Testing
{
  /**
   * The quarter circle of radius 0.4 on a small adaptive mesh (levels 3-6,
   * eps = 4h): the input of ramp_up_steps, regrow_step_size and
   * augmented_lagrangian_2d, which add
   * their time stepping, Newton and output settings.
   */
  inline const std::string quarter_circle_level6 = R"(
set Dimension = 2
subsection Geometry
  set Shape = quarter circle
  set Radius = 0.4
end
subsection Mesh
  set Finest level = 6
  set Coarsest level = 3
end
subsection Phase field
  set Epsilon = 4*h
end
)";

  /**
   * The damaged circle of thesis Fig. 5.6 on a small adaptive mesh (level
   * 6, eta = 1, 64-pixel pictures): the input of edge_restoration_circle,
   * edge_restoration_augmented_lagrangian and checkpoint_restoration, which
   * add their time stepping and output.
   */
  inline const std::string damaged_circle_restoration = R"(
set Dimension = 2
subsection Geometry
  set Shape  = damaged circle
  set Center = 0.5, 0
  set Radius = 0.45
end
subsection Restoration
  set Eta    = 1
  set Region = 0.25, 0.25, 0.75, 0.75
  set Damage = 0.375, 0.3, 0.625, 0.6
  set Picture resolution = 64
end
subsection Mesh
  set Finest level = 6
  set Coarsest level = 3
end
)";

  /**
   * Run edge_restoration on the parameters in @p prm_text (output
   * directory "results") and return the rows of statistics.csv.
   */
  inline std::vector<std::vector<double>>
  run_restoration(const std::string &prm_text, std::vector<std::string> &header)
  {
    dealii::ParameterHandler prm;
    PhaseField::EdgeRestorationParameters::declare_parameters(prm);
    prm.parse_input_from_string(prm_text +
                                "\nset Output directory = results\n");
    PhaseField::EdgeRestorationParameters parameters;
    parameters.parse_parameters(prm);
    PhaseField::RestorationProblem(parameters).run();
    return read_csv("results/statistics.csv", header);
  }

  /**
   * Print the restoration columns and check that the weighted energy
   * never increases and falls by more than 0.1% in the first step (the
   * tests' inputs have corners and gaps: measured 72% and 6.6%; a solver
   * that does nothing keeps the energy), and that U outside the region
   * never changes.
   */
  inline void
  check_restoration_table(const std::vector<std::vector<double>> &rows,
                          const std::vector<std::string>         &header)
  {
    print_columns(rows,
                  header,
                  {"step",
                   "willmore_energy",
                   "area_energy",
                   "weighted_energy",
                   "fixed_u_deviation"});
    const int energy     = column(header, "weighted_energy");
    const int fixed      = column(header, "fixed_u_deviation");
    bool      decreasing = true, unchanged = true;
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        unchanged = unchanged && rows[i][fixed] == 0;
        if (i > 0)
          decreasing = decreasing && rows[i][energy] <= rows[i - 1][energy];
      }
    // relative decrease in step 1 that a moving solver certainly exceeds
    constexpr double first_step_decrease = 1e-3;
    decreasing                           = decreasing && rows.size() > 1 &&
                 rows[1][energy] < (1 - first_step_decrease) * rows[0][energy];
    log() << "weighted energy decreasing at every step, by more than 0.1% "
             "in step 1: "
          << (decreasing ? "yes" : "NO") << '\n'
          << "U outside the region unchanged: " << (unchanged ? "yes" : "NO")
          << std::endl;
  }
  /**
   * Radius of a quarter circle (or of a quarter cylinder of unit length)
   * from the measure of its inside phase: r = sqrt(4 m / pi).
   */
  inline double
  quarter_circle_radius(const std::vector<double>      &row,
                        const std::vector<std::string> &header)
  {
    return std::sqrt(4 * row[column(header, "inside_measure")] / M_PI);
  }

  /**
   * Check a quarter-circle run (r0 = @p r0 at the origin) against the
   * exact Willmore flow r(t) = (2t + r0^4)^(1/4) (also the law of a
   * quarter cylinder in 3D): in every step after step 0 the radius from
   * inside_measure is within 1%, the Willmore energy is within
   * @p energy_tolerance of pi/(4r) and does not increase, and Newton needed
   * at most 10 iterations; and the growth of the radius since step 0 is
   * within @p growth_tolerance of the exact growth r(t) - r0. The radius
   * itself moves little in a few steps: only its growth tells a flow at
   * half or double speed, a solver that does nothing or a Willmore term of
   * the wrong sign (the circle shrinks) from the right one. Logs one line
   * per verdict.
   */
  inline void
  check_quarter_circle(const std::vector<std::vector<double>> &rows,
                       const std::vector<std::string>         &header,
                       const double                            r0,
                       const double                            energy_tolerance,
                       const double                            growth_tolerance)
  {
    const double pi = M_PI;
    bool         ok = true, growth_ok = rows.size() > 1;
    const double r_start = quarter_circle_radius(rows[0], header);
    for (unsigned int i = 1; i < rows.size(); ++i)
      {
        const auto  &row        = rows[i];
        const double t          = row[column(header, "time")];
        const double r_exact    = std::pow(2 * t + std::pow(r0, 4), 0.25);
        const double r_measured = quarter_circle_radius(row, header);
        const double w          = row[column(header, "willmore_energy")];
        ok = ok && std::abs(r_measured / r_exact - 1) < 0.01;
        ok = ok && std::abs(w / (pi / (4 * r_exact)) - 1) < energy_tolerance;
        ok = ok && w <= rows[i - 1][column(header, "willmore_energy")];
        ok = ok && row[column(header, "newton_iterations")] <= 10;
        const double growth = (r_measured - r_start) / (r_exact - r0);
        growth_ok = growth_ok && std::abs(growth - 1) < growth_tolerance;
      }
    log() << "radius within 1%, Willmore energy within "
          << std::round(100 * energy_tolerance)
          << "% and decreasing: " << (ok ? "yes" : "NO") << std::endl;
    log() << "radius growth within " << std::round(100 * growth_tolerance)
          << "% of the exact growth (2t + r0^4)^(1/4) - r0: "
          << (growth_ok ? "yes" : "NO") << std::endl;
  }
} // namespace Testing

namespace Testing
{
  /** What a run leaves: its statistics and the l2 norms of its fields. */
  struct RunResult
  {
    std::vector<std::string>         header;
    std::vector<std::vector<double>> rows;
    std::vector<double>              field_norms;
  };

  /**
   * Largest relative difference of @p a and @p b over all rows and all
   * columns but wall_seconds and those in @p ignored (infinite if the
   * tables differ in shape or an entry is NaN in one table only; NaN in
   * both counts as equal).
   */
  inline double
  max_relative_difference(const RunResult                &a,
                          const RunResult                &b,
                          const std::vector<std::string> &ignored = {})
  {
    if (a.rows.size() != b.rows.size() || a.header != b.header)
      return std::numeric_limits<double>::infinity();
    double max = 0;
    for (unsigned int j = 0; j < a.header.size(); ++j)
      if (a.header[j] != "wall_seconds" &&
          std::find(ignored.begin(), ignored.end(), a.header[j]) ==
            ignored.end())
        for (unsigned int i = 0; i < a.rows.size(); ++i)
          {
            const double x = a.rows[i][j], y = b.rows[i][j];
            if (std::isnan(x) && std::isnan(y))
              continue;
            if (std::isnan(x) || std::isnan(y))
              return std::numeric_limits<double>::infinity();
            max =
              std::max(max, std::abs(x - y) / std::max(std::abs(x), 1e-300));
          }
    return max;
  }

  /**
   * Run the program of @p Problem (constructed from @p Parameters) on
   * @p base_prm for @p n_steps steps (Time stepping / Number of steps),
   * resuming from a checkpoint if @p resume (Checkpoint / Resume), with
   * output directory @p directory, as the checkpoint tests do.
   */
  template <typename Parameters, typename Problem>
  RunResult
  run_with_checkpoints(const std::string &base_prm,
                       const std::string &directory,
                       const unsigned int n_steps,
                       const bool         resume)
  {
    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    prm.parse_input_from_string(
      base_prm + "subsection Time stepping\n set Number of steps = " +
      std::to_string(n_steps) + "\nend\nsubsection Checkpoint\n set Resume = " +
      (resume ? "true" : "false") +
      "\nend\nset Output directory = " + directory + "\n");
    Parameters parameters;
    parameters.parse_parameters(prm);
    Problem problem(parameters);
    problem.run();
    RunResult result;
    for (unsigned int b = 0; b < problem.state().n_blocks(); ++b)
      result.field_norms.push_back(problem.state().block(b).l2_norm());
    MPI_Barrier(MPI_COMM_WORLD);
    result.rows = read_csv(directory + "/statistics.csv", result.header);
    return result;
  }
} // namespace Testing

#endif
