#include <algorithm>
#include <cmath>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>
#include <filesystem>
#include <iomanip>
#include <phasefield/core/statistics.h>
#include <phasefield/problems/biharmonic_problem.h>
#include <phasefield/schemes/scheme_registry.h>
#include <phasefield/schemes/time_stepping_scheme.h>

namespace PhaseField
{
  using namespace dealii;

  namespace BiharmonicSolutions
  {
    namespace
    {
      /** Growth rate of the forced solutions (Lemma 4.5: e^{20t} - 1). */
      constexpr double growth_rate = 20;

      /** g(s) = s^4 - 2s^3 + s and its derivatives (Lemma 4.5). */
      double
      g(const double s)
      {
        return s * s * s * s - 2 * s * s * s + s;
      }
      double
      d_g(const double s)
      {
        return 4 * s * s * s - 6 * s * s + 1;
      }
      double
      d2_g(const double s)
      {
        return 12 * s * s - 12 * s;
      }
      constexpr double d4_g = 24;

      /** prod_{i != skip1, skip2} g(x_i). */
      template <int dim>
      double
      product_of_g(const Point<dim> &p,
                   const int         skip1 = -1,
                   const int         skip2 = -1)
      {
        double product = 1;
        for (int i = 0; i < dim; ++i)
          if (i != skip1 && i != skip2)
            product *= g(p[i]);
        return product;
      }

      /** phi = prod_i g(x_i) (Lemma 4.5): phi = Lap phi = 0 on the boundary. */
      template <int dim>
      class ProductOfG : public Function<dim>
      {
      public:
        double
        value(const Point<dim> &p, const unsigned int = 0) const override
        {
          return product_of_g(p);
        }
        Tensor<1, dim>
        gradient(const Point<dim> &p, const unsigned int = 0) const override
        {
          Tensor<1, dim> grad;
          for (int i = 0; i < dim; ++i)
            grad[i] = d_g(p[i]) * product_of_g(p, i);
          return grad;
        }
      };

      /**
       * Lap^2 prod g = sum_i g'''' prod_{j != i} g
       *              + 2 sum_{i<j} g''(x_i) g''(x_j) prod_{k != i,j} g.
       */
      template <int dim>
      class BilaplacianOfProductOfG : public Function<dim>
      {
      public:
        double
        value(const Point<dim> &p, const unsigned int = 0) const override
        {
          double result = 0;
          for (int i = 0; i < dim; ++i)
            {
              result += d4_g * product_of_g(p, i);
              for (int j = i + 1; j < dim; ++j)
                result += 2 * d2_g(p[i]) * d2_g(p[j]) * product_of_g(p, i, j);
            }
          return result;
        }
      };

      /**
       * factor * sum_i cos(k x_i), an eigenfunction of Lap^2 with
       * eigenvalue k^4; d_n phi = d_n Lap phi = 0 on the boundary of the
       * unit cube for k = pi, periodic on the unit cell for k = 2 pi.
       */
      template <int dim>
      class CosineSum : public Function<dim>
      {
      public:
        CosineSum(const double wave_number, const double factor = 1)
          : k(wave_number)
          , factor(factor)
        {}
        double
        value(const Point<dim> &p, const unsigned int = 0) const override
        {
          double sum = 0;
          for (int i = 0; i < dim; ++i)
            sum += std::cos(k * p[i]);
          return factor * sum;
        }
        Tensor<1, dim>
        gradient(const Point<dim> &p, const unsigned int = 0) const override
        {
          Tensor<1, dim> grad;
          for (int i = 0; i < dim; ++i)
            grad[i] = -factor * k * std::sin(k * p[i]);
          return grad;
        }

      private:
        const double k;
        const double factor;
      };

      /** u = A(t) phi(x) as a Function (value and gradient). */
      template <int dim>
      class SeparatedFunction : public Function<dim>
      {
      public:
        explicit SeparatedFunction(const SeparatedSolution<dim> &solution)
          : solution(solution)
        {}
        double
        value(const Point<dim> &p, const unsigned int = 0) const override
        {
          return solution.amplitude(this->get_time()) *
                 solution.shape->value(p);
        }
        Tensor<1, dim>
        gradient(const Point<dim> &p, const unsigned int = 0) const override
        {
          return solution.amplitude(this->get_time()) *
                 solution.shape->gradient(p);
        }

      private:
        const SeparatedSolution<dim> &solution;
      };
    } // namespace



    template <int dim>
    SeparatedSolution<dim>
    exact_solution(const BiharmonicBoundaryConditions bc)
    {
      SeparatedSolution<dim> s;
      const auto             growing = [](const double t) {
        return std::expm1(growth_rate * t);
      };
      const auto growing_derivative = [](const double t) {
        return growth_rate * std::exp(growth_rate * t);
      };
      switch (bc)
        {
          case BiharmonicBoundaryConditions::dirichlet:
            s.amplitude            = growing;
            s.amplitude_derivative = growing_derivative;
            s.shape                = std::make_unique<ProductOfG<dim>>();
            s.shape_bilaplacian =
              std::make_unique<BilaplacianOfProductOfG<dim>>();
            s.forced = true;
            break;
            case BiharmonicBoundaryConditions::neumann: {
              const double k  = numbers::PI;
              const double k4 = std::pow(k, 4);
              s.amplitude = [k4](const double t) { return std::exp(-k4 * t); };
              s.amplitude_derivative = [k4](const double t) {
                return -k4 * std::exp(-k4 * t);
              };
              s.shape             = std::make_unique<CosineSum<dim>>(k);
              s.shape_bilaplacian = std::make_unique<CosineSum<dim>>(k, k4);
              s.forced            = false;
              break;
            }
            case BiharmonicBoundaryConditions::periodic: {
              const double k         = 2 * numbers::PI;
              s.amplitude            = growing;
              s.amplitude_derivative = growing_derivative;
              s.shape                = std::make_unique<CosineSum<dim>>(k);
              s.shape_bilaplacian =
                std::make_unique<CosineSum<dim>>(k, std::pow(k, 4));
              s.forced = true;
              break;
            }
        }
      return s;
    }



    template <int dim>
    std::unique_ptr<Function<dim>>
    SeparatedSolution<dim>::function() const
    {
      return std::make_unique<SeparatedFunction<dim>>(*this);
    }



    template struct SeparatedSolution<2>;
    template struct SeparatedSolution<3>;
    template SeparatedSolution<2>
    exact_solution<2>(const BiharmonicBoundaryConditions);
    template SeparatedSolution<3>
    exact_solution<3>(const BiharmonicBoundaryConditions);
  } // namespace BiharmonicSolutions



  namespace
  {
    /**
     * Relative residual reduction of GMRES preconditioned with the
     * factorisation (direct type; the iterative type takes `Linear solver /
     * Tolerance`).
     */
    constexpr double direct_solver_tolerance = 1e-12;
    /**
     * GMRES iterations allowed per solve of the direct type; with the exact
     * factorisation of the same matrix as preconditioner one iteration
     * suffices.
     */
    constexpr unsigned int direct_solver_max_iterations = 100;
    /**
     * Progress lines printed per level (about one per tenth of its steps).
     */
    constexpr unsigned int n_progress_lines = 10;
    /**
     * Newton's method on the linear system: one iteration solves a step
     * exactly (the residual drops to round-off, far below this); a second
     * one would only polish round-off.
     */
    constexpr double       newton_relative_tolerance = 1e-10;
    constexpr unsigned int newton_max_iterations     = 2;

    /**
     * The uniform mesh of one level, its boundary conditions and the
     * solver of the parameters.
     */
    template <int dim>
    typename Discretization<dim>::Settings
    uniform_mesh(const unsigned int          level,
                 const BiharmonicParameters &parameters)
    {
      const BiharmonicBoundaryConditions bc =
        parameters.problem.boundary_conditions;
      typename Discretization<dim>::Settings settings{};
      settings.solver =
        resolve_solver_choice(parameters.linear_solver,
                              parameters.time.scheme.name,
                              dim,
                              bc == BiharmonicBoundaryConditions::periodic);
      settings.mesh.finest_level = settings.mesh.coarsest_level = level;
      settings.mesh.adaptive                                    = false;
      settings.mesh.stiffness_quadrature = StiffnessQuadrature::gauss;
      settings.boundary_conditions =
        bc == BiharmonicBoundaryConditions::dirichlet ?
          BoundaryConditions::dirichlet :
          (bc == BiharmonicBoundaryConditions::periodic ?
             BoundaryConditions::periodic :
             BoundaryConditions::natural);
      return settings;
    }

    /** The nested scheme of the biharmonic model with forcing @p f. */
    template <int dim>
    SchemeSettings
    biharmonic_scheme(const BiharmonicParameters &parameters,
                      const SolverChoice         &solver,
                      const double                inner_tau,
                      const Vector               *f)
    {
      SchemeSettings s;
      s.scheme                    = parameters.time.scheme;
      s.epsilon                   = 1;
      s.inner_tau                 = inner_tau;
      s.double_well               = false;
      s.outer_energy.forcing      = f;
      s.newton.relative_tolerance = newton_relative_tolerance;
      s.newton.absolute_tolerance = 0;
      s.newton.max_iterations     = newton_max_iterations;
      s.newton.max_damping_steps  = 0;
      s.newton.watchdog_factor    = 1;
      s.newton.max_step_halvings  = 0;
      s.linear_solver             = parameters.linear_solver;
      s.solver                    = solver;
      if (s.solver.type == LinearSolverType::direct)
        {
          s.linear_solver.relative_tolerance = direct_solver_tolerance;
          s.linear_solver.max_iterations     = direct_solver_max_iterations;
        }
      return s;
    }
  } // namespace



  template <int dim>
  BiharmonicProblem<dim>::BiharmonicProblem(
    const BiharmonicParameters &parameters,
    const unsigned int          level)
    : biharmonic_parameters(parameters)
    , level(level)
    , h(std::ldexp(1.0, -static_cast<int>(level)))
    , step_sizes(parameters.time.step_sizes(h))
    , mpi_communicator(MPI_COMM_WORLD)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , computing_timer(mpi_communicator,
                      pcout,
                      TimerOutput::never,
                      TimerOutput::wall_times)
    , discretization(uniform_mesh<dim>(level, parameters), mpi_communicator)
    , exact(BiharmonicSolutions::exact_solution<dim>(
        parameters.problem.boundary_conditions))
    , exact_solution(exact.function())
  {}



  template <int dim>
  void
  BiharmonicProblem<dim>::setup_system()
  {
    TimerOutput::Scope t(computing_timer, "setup");
    discretization.create_mesh(nullptr, 1.);
    const LumpedOperators<dim> &operators = discretization.get_operators();
    scheme                                = create_time_stepping_scheme<dim>(
      biharmonic_scheme<dim>(biharmonic_parameters,
                             discretization.get_settings().solver,
                             step_sizes.inner_tau,
                             exact.forced ? &forcing_vector : nullptr),
      discretization,
      pcout);
    discretization.reinit(solution, scheme->n_fields());
    forcing_vector.reinit(operators.locally_owned_dofs, mpi_communicator);

    // The time-independent parts of the nodal forcing M I_h(f).
    forcing_shape.reinit(forcing_vector);
    forcing_bilaplacian.reinit(forcing_vector);
    if (exact.forced)
      {
        discretization.interpolate(*exact.shape, forcing_shape);
        discretization.interpolate(*exact.shape_bilaplacian,
                                   forcing_bilaplacian);
        forcing_shape.scale(operators.lumped_mass);
        forcing_bilaplacian.scale(operators.lumped_mass);
      }
  }



  template <int dim>
  void
  BiharmonicProblem<dim>::assemble_forcing(const double time)
  {
    // M I_h(f) = A'(t) M I_h(phi) + A(t) M I_h(Lap^2 phi); zero at
    // constrained DoFs, where the lumped mass is zero.
    forcing_vector = 0;
    forcing_vector.add(exact.amplitude_derivative(time),
                       forcing_shape,
                       exact.amplitude(time),
                       forcing_bilaplacian);
  }



  template <int dim>
  void
  BiharmonicProblem<dim>::compute_errors(const double           time,
                                         BiharmonicLevelResult &result)
  {
    TimerOutput::Scope t(computing_timer, "errors");
    Vector             u(solution.block(0));
    discretization.get_constraints().distribute(u);
    exact_solution->set_time(time);
    result.l2_error =
      discretization.error(u, *exact_solution, VectorTools::L2_norm);
    result.h1_error =
      discretization.error(u, *exact_solution, VectorTools::H1_norm);
  }



  template <int dim>
  BiharmonicLevelResult
  BiharmonicProblem<dim>::run()
  {
    Timer wall_timer;
    setup_system();

    // U^0 = I_h u(0); V and P as the scheme initialises them (nested:
    // Algorithm 3.1; augmented Lagrangian: P = Initial multiplier).
    exact_solution->set_time(0);
    discretization.interpolate(*exact_solution, solution.block(0));
    discretization.get_operators().zero_constrained(solution.block(0));
    scheme->initialize(solution, step_sizes.tau);

    double             time = 0;
    StepReport         report, total_report;
    const unsigned int progress_interval =
      std::max(1u, step_sizes.n_steps / n_progress_lines);
    for (unsigned int step = 1; step <= step_sizes.n_steps; ++step)
      {
        TimerOutput::Scope t(computing_timer, "time steps");
        time = step * step_sizes.tau;
        if (exact.forced)
          assemble_forcing(time);
        old_solution = solution;
        report       = scheme->advance(old_solution, solution, step_sizes.tau);
        AssertThrow(report.converged,
                    ExcMessage("Biharmonic time step " + std::to_string(step) +
                               " did not converge (nested: the linear solve "
                               "did not reach round-off; augmented "
                               "Lagrangian: raise the limits of subsection "
                               "Augmented Lagrangian)."));
        total_report = combine(total_report, report);
        if (step % progress_interval == 0 || step == step_sizes.n_steps)
          pcout << "  level " << level << ": step " << step << " of "
                << step_sizes.n_steps << ", t = " << time << ", "
                << std::round(10 * wall_timer.wall_time()) / 10 << " s"
                << std::endl;
      }

    BiharmonicLevelResult result;
    result.level     = level;
    result.h         = h;
    result.tau       = step_sizes.tau;
    result.inner_tau = step_sizes.inner_tau;
    result.n_steps   = step_sizes.n_steps;
    result.time      = time;
    result.n_dofs    = discretization.n_dofs();
    result.relative_residual =
      report.final_residual_norm / report.initial_residual_norm;
    result.n_factorizations = scheme->n_factorizations();
    result.al_iterations =
      static_cast<unsigned int>(total_report.count("al_iterations"));
    result.tr_iterations =
      static_cast<unsigned int>(total_report.count("tr_iterations"));
    result.linear_iterations = total_report.linear_iterations;
    compute_errors(time, result);
    result.wall_seconds = wall_timer.wall_time();
    result.section_seconds =
      computing_timer.get_summary_data(TimerOutput::total_wall_time);
    return result;
  }



  template <int dim>
  std::vector<BiharmonicLevelResult>
  run_biharmonic_convergence_study(const BiharmonicParameters &parameters)
  {
    const MPI_Comm     comm = MPI_COMM_WORLD;
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(comm) == 0);
    create_output_directory(parameters.output_directory, comm);

    pcout << "biharmonic_flow: " << dim << "D, boundary conditions <"
          << parameters.problem.boundary_conditions_name()
          << ">, Tau = " << parameters.time.tau_expression
          << ", Inner tau = " << parameters.time.inner_tau_expression
          << ", final time " << parameters.time.final_time << ", "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
          << std::endl;

    StatisticsFile csv(
      parameters.output_directory + "/convergence.csv",
      {"level", "h", "tau", "inner_tau", "time", "l2_error", "h1_error"},
      comm);
    ConvergenceTable                   table;
    std::vector<BiharmonicLevelResult> results;
    for (const unsigned int level : parameters.convergence.levels)
      {
        const BiharmonicLevelResult r =
          BiharmonicProblem<dim>(parameters, level).run();
        results.push_back(r);
        csv.add_row({double(r.level),
                     r.h,
                     r.tau,
                     r.inner_tau,
                     r.time,
                     r.l2_error,
                     r.h1_error});
        pcout << "level " << r.level << ": h = " << r.h << ", tau = " << r.tau
              << ", inner tau = " << r.inner_tau << ", " << r.n_steps
              << " steps to t = " << r.time << ", " << r.n_dofs
              << " DoFs per field, " << r.n_factorizations
              << " preconditioner set-up(s), " << r.al_iterations << " AL / "
              << r.tr_iterations << " trust-region / " << r.linear_iterations
              << " Krylov iterations, relative residual "
              << std::setprecision(2) << r.relative_residual
              << std::setprecision(6) << "; L2 error " << r.l2_error
              << ", H1 error " << r.h1_error << " [" << std::setprecision(3)
              << r.wall_seconds << " s:";
        for (const auto &section : r.section_seconds)
          pcout << ' ' << section.first << ' ' << section.second << " s,";
        pcout << "]" << std::setprecision(6) << std::endl;

        table.add_value("level", r.level);
        table.add_value("cells", std::pow(2., dim * double(r.level)));
        table.add_value("tau", r.tau);
        table.add_value("inner tau", r.inner_tau);
        table.add_value("steps", r.n_steps);
        table.add_value("L2", r.l2_error);
        table.add_value("H1", r.h1_error);
      }

    // EOC per halving of h, also for levels that are not consecutive.
    for (const std::string column : {"L2", "H1"})
      {
        table.evaluate_convergence_rates(column,
                                         "cells",
                                         ConvergenceTable::reduction_rate_log2,
                                         dim);
        table.set_scientific(column, true);
        table.set_precision(column, 4);
      }
    for (const std::string column : {"tau", "inner tau"})
      {
        table.set_scientific(column, true);
        table.set_precision(column, 3);
      }
    table.set_scientific("cells", false);
    table.set_precision("cells", 0);
    pcout << "\nExperimental orders of convergence (errors at t = "
          << parameters.time.final_time << "):\n";
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      table.write_text(std::cout);
    print_peak_memory(pcout, comm);
    return results;
  }



  template class BiharmonicProblem<2>;
  template class BiharmonicProblem<3>;
  template std::vector<BiharmonicLevelResult>
  run_biharmonic_convergence_study<2>(const BiharmonicParameters &);
  template std::vector<BiharmonicLevelResult>
  run_biharmonic_convergence_study<3>(const BiharmonicParameters &);
} // namespace PhaseField
