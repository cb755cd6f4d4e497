#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <phasefield/narrow_band.h>
#include <phasefield/semi_implicit_scheme.h>
#include <phasefield/shapes.h>
#include <phasefield/statistics.h>
#include <phasefield/willmore_problem.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * The operations of @p system that every scheme provides under the
     * same names (the residual differs in its arguments).
     */
    template <class SchemeType>
    void
    connect_scheme(const SchemeType &scheme, NonlinearSystem &system)
    {
      using BlockVector = TrilinosWrappers::MPI::BlockVector;
      system.norm       = [&scheme](const BlockVector &r) {
        return scheme.residual_norm(r);
      };
      system.solve = [&scheme](const BlockVector   &z,
                               const BlockVector   &r,
                               BlockVector         &dz,
                               ReducedSystemSolver &solver) {
        return scheme.solve_newton_system(z, r, dz, solver);
      };
      system.term_scale = [&scheme](const BlockVector &z) {
        return scheme.term_scale(z);
      };
    }



    /**
     * deal.II's smoothing on refinement and coarsening, without
     * eliminate_unrefined_islands if @p options ask so.
     */
    template <int dim>
    typename Triangulation<dim>::MeshSmoothing
    mesh_smoothing(const WillmoreProblemOptions<dim> &options)
    {
      using Tria = Triangulation<dim>;
      if (options.refine_unrefined_islands)
        return typename Tria::MeshSmoothing(Tria::smoothing_on_refinement |
                                            Tria::smoothing_on_coarsening);
      return
        typename Tria::MeshSmoothing(Tria::limit_level_difference_at_vertices |
                                     Tria::smoothing_on_coarsening);
    }



    /** @p head followed by @p tail. */
    template <typename T>
    std::vector<T>
    concatenate(std::vector<T> head, const std::vector<T> &tail)
    {
      head.insert(head.end(), tail.begin(), tail.end());
      return head;
    }
  } // namespace



  template <int dim>
  WillmoreProblem<dim>::WillmoreProblem(
    const WillmoreParameters          &parameters,
    const WillmoreProblemOptions<dim> &options)
    : prm(parameters)
    , options(options)
    , mpi_communicator(MPI_COMM_WORLD)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , computing_timer(mpi_communicator,
                      pcout,
                      TimerOutput::never,
                      TimerOutput::wall_times)
    , triangulation(mpi_communicator, mesh_smoothing<dim>(options))
    , fe(1)
    , dof_handler(triangulation)
  {
    signed_distance = options.signed_distance ?
                        options.signed_distance :
                        Shapes::create_signed_distance<dim>(prm.geometry);

    LinearSolverType type = prm.linear_solver.type;
    if (type == LinearSolverType::automatic)
      type =
        (dim == 2 ? LinearSolverType::direct : LinearSolverType::iterative);
    // the semi-implicit scheme's Jacobian is not symmetric
    linear_solver = std::make_unique<ReducedSystemSolver>(
      type,
      prm.linear_solver.relative_tolerance,
      prm.linear_solver.max_iterations,
      /*symmetric=*/prm.model.scheme == Scheme::nested);
  }



  template <int dim>
  unsigned int
  WillmoreProblem<dim>::n_fields() const
  {
    return prm.model.scheme == Scheme::nested ? 3 : 2;
  }



  template <int dim>
  NestedCoefficients
  WillmoreProblem<dim>::coefficients(const double tau) const
  {
    NestedCoefficients c;
    c.epsilon     = prm.model.epsilon;
    c.tau         = tau;
    c.inner_tau   = prm.model.inner_tau;
    c.double_well = true;
    c.area_weight = options.area_weight;
    c.fixed_u     = options.u_is_free ? &fixed_u_dofs : nullptr;
    return c;
  }



  template <int dim>
  void
  WillmoreProblem<dim>::setup_fixed_u()
  {
    fixed_u_dofs.clear();
    fixed_u_dofs.set_size(dof_handler.n_dofs());
    initial_u.reinit(operators.locally_owned_dofs, mpi_communicator);
    const Shapes::PhaseFieldProfile<dim> u0(*signed_distance,
                                            prm.model.epsilon);
    VectorTools::interpolate(dof_handler, u0, initial_u);
    constraints.distribute(initial_u);
    if (!options.u_is_free)
      return;
    std::map<types::global_dof_index, Point<dim>> support_points;
    DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                         dof_handler,
                                         support_points);
    for (const auto &[dof, point] : support_points)
      if (!options.u_is_free(point))
        fixed_u_dofs.add_index(dof);
    fixed_u_dofs.compress();
  }



  template <int dim>
  void
  WillmoreProblem<dim>::reset_fixed_u()
  {
    Vector            &u = solution.block(Field::U);
    const unsigned int n = u.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      if (fixed_u_dofs.is_element(
            operators.locally_owned_dofs.nth_index_in_set(i)))
        u.begin()[i] = initial_u.begin()[i];
  }



  template <int dim>
  double
  WillmoreProblem<dim>::fixed_u_deviation() const
  {
    const Vector      &u         = solution.block(Field::U);
    const unsigned int n         = u.locally_owned_size();
    double             deviation = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (fixed_u_dofs.is_element(
            operators.locally_owned_dofs.nth_index_in_set(i)))
        deviation =
          std::max(deviation, std::abs(u.begin()[i] - initial_u.begin()[i]));
    return Utilities::MPI::max(deviation, mpi_communicator);
  }



  template <int dim>
  std::vector<std::string>
  WillmoreProblem<dim>::extra_columns() const
  {
    if (!options.restoration())
      return {};
    return {"weighted_energy", "fixed_u_deviation"};
  }



  template <int dim>
  std::vector<double>
  WillmoreProblem<dim>::extra_values(const Energies &energies) const
  {
    if (!options.restoration())
      return {};
    return {energies.willmore + options.area_weight * energies.area,
            fixed_u_deviation()};
  }



  template <int dim>
  double
  WillmoreProblem<dim>::weighted_energy() const
  {
    const Energies e = compute_energies();
    return e.willmore + options.area_weight * e.area;
  }



  template <int dim>
  double
  WillmoreProblem<dim>::dissipation(const double tau) const
  {
    Vector difference(solution.block(Field::U));
    difference -= old_solution.block(Field::U);
    // eps ||U - U^k||^2 / (2 tau), in the units of the energies (3/4)
    return 0.75 * prm.model.epsilon / (2 * tau) *
           operators.mass_product(difference, difference);
  }



  template <int dim>
  void
  WillmoreProblem<dim>::create_initial_mesh()
  {
    TimerOutput::Scope t(computing_timer, "mesh: initial");
    GridGenerator::hyper_cube(triangulation, 0., 1.);
    if (!prm.mesh.adaptive)
      {
        triangulation.refine_global(prm.mesh.finest_level);
        return;
      }
    triangulation.refine_global(prm.mesh.coarsest_level);
    NarrowBand::refine_around_zero_level_set(triangulation,
                                             *signed_distance,
                                             prm.mesh.band_width,
                                             prm.model.epsilon,
                                             prm.mesh.finest_level);
  }



  template <int dim>
  void
  WillmoreProblem<dim>::setup_system()
  {
    TimerOutput::Scope t(computing_timer, "setup");
    dof_handler.distribute_dofs(fe);

    IndexSet locally_relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);
    constraints.clear();
    constraints.reinit(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    constraints.close();

    operators.reinit(dof_handler,
                     constraints,
                     mpi_communicator,
                     prm.mesh.stiffness_quadrature);
    linear_solver->reset();
    reinit_vector(solution);
    reinit_vector(old_solution);
    if (options.restoration())
      setup_fixed_u();
  }



  template <int dim>
  void
  WillmoreProblem<dim>::reinit_vector(BlockVector &v) const
  {
    v.reinit(std::vector<IndexSet>(n_fields(), operators.locally_owned_dofs),
             mpi_communicator);
  }



  template <int dim>
  void
  WillmoreProblem<dim>::distribute_constraints(BlockVector &v) const
  {
    for (unsigned int b = 0; b < v.n_blocks(); ++b)
      constraints.distribute(v.block(b));
  }



  template <int dim>
  void
  WillmoreProblem<dim>::initialize_fields()
  {
    TimerOutput::Scope                   t(computing_timer, "initialisation");
    const Shapes::PhaseFieldProfile<dim> u0(*signed_distance,
                                            prm.model.epsilon);
    VectorTools::interpolate(dof_handler, u0, solution.block(Field::U));
    if (prm.model.scheme == Scheme::nested)
      {
        const NestedScheme<dim> scheme(operators, coefficients(prm.model.tau));
        // its own solver: the factorisations of K are no use for S later
        ReducedSystemSolver solver(linear_solver->type(),
                                   prm.linear_solver.relative_tolerance,
                                   prm.linear_solver.max_iterations);
        constexpr double    initialization_tolerance = 1e-10;
        scheme.initialize_v_and_p(solution, solver, initialization_tolerance);
      }
    else
      {
        const SemiImplicitScheme<dim> scheme(operators,
                                             prm.model.epsilon,
                                             prm.model.tau,
                                             solution);
        scheme.initialize_f(solution);
      }
    distribute_constraints(solution);
  }



  template <int dim>
  StepReport
  WillmoreProblem<dim>::solve_time_step(const double tau)
  {
    TimerOutput::Scope t(computing_timer, "newton");
    NonlinearSystem    system;
    system.distribute_constraints = [this](BlockVector &z) {
      distribute_constraints(z);
    };
    // The scheme objects are captured by the closures; they live until
    // newton_solve() returns.
    if (prm.model.scheme == Scheme::nested)
      {
        const NestedScheme<dim> scheme(operators, coefficients(tau));
        const Vector           &old_u = old_solution.block(Field::U);
        system.residual = [&](const BlockVector &z, BlockVector &r) {
          scheme.residual(old_u, z, r);
        };
        connect_scheme(scheme, system);
        if (!options.restoration())
          return newton_solve(system,
                              solution,
                              prm.newton,
                              *linear_solver,
                              pcout,
                              prm.output.verbose);

        // Edge restoration: minimise the outer energy over U with V, P
        // re-solved for every trial U, so that the energy decreases at
        // every iteration (minimizing_newton_solve()). The inner problem
        // is convex; its own solver keeps the factorisation of K(V).
        ReducedSystemSolver inner_solver(LinearSolverType::direct,
                                         prm.linear_solver.relative_tolerance,
                                         prm.linear_solver.max_iterations);
        system.project_and_merit = [&](BlockVector &z) {
          scheme.solve_inner_problem(z, inner_solver, inner_tolerance);
          return scheme.outer_energy(old_u, z);
        };
        system.solve_shifted = [&](const BlockVector   &z,
                                   const BlockVector   &r,
                                   BlockVector         &dz,
                                   ReducedSystemSolver &solver,
                                   const double         shift) {
          NestedCoefficients shifted = coefficients(tau);
          shifted.u_shift            = shift;
          return NestedScheme<dim>(operators, shifted)
            .solve_newton_system(z, r, dz, solver);
        };
        return minimizing_newton_solve(system,
                                       solution,
                                       prm.newton,
                                       *linear_solver,
                                       pcout,
                                       prm.output.verbose);
      }

    const SemiImplicitScheme<dim> scheme(operators,
                                         prm.model.epsilon,
                                         tau,
                                         old_solution);
    system.residual = [&](const BlockVector &z, BlockVector &r) {
      scheme.residual(z, r);
    };
    connect_scheme(scheme, system);
    return newton_solve(
      system, solution, prm.newton, *linear_solver, pcout, prm.output.verbose);
  }



  template <int dim>
  void
  WillmoreProblem<dim>::solve_inner_problem(const double tau)
  {
    ReducedSystemSolver solver(LinearSolverType::direct,
                               prm.linear_solver.relative_tolerance,
                               prm.linear_solver.max_iterations);
    NestedScheme<dim>(operators, coefficients(tau))
      .solve_inner_problem(solution, solver, inner_tolerance);
  }



  template <int dim>
  Energies
  WillmoreProblem<dim>::compute_energies() const
  {
    if (prm.model.scheme == Scheme::nested)
      return NestedScheme<dim>(operators, coefficients(prm.model.tau))
        .energies(solution);
    return SemiImplicitScheme<dim>(operators,
                                   prm.model.epsilon,
                                   prm.model.tau,
                                   old_solution)
      .energies(solution);
  }



  template <int dim>
  void
  WillmoreProblem<dim>::compute_curvature(Vector &curvature) const
  {
    if (prm.model.scheme == Scheme::nested)
      {
        // (U - V) / inner tau
        curvature = solution.block(Field::U);
        curvature -= solution.block(Field::V);
        curvature /= prm.model.inner_tau;
      }
    else
      {
        // -F / eps, the same quantity (see SemiImplicitScheme)
        curvature = solution.block(SemiImplicitField::F);
        curvature /= -prm.model.epsilon;
      }
  }



  template <int dim>
  void
  WillmoreProblem<dim>::refine_mesh()
  {
    TimerOutput::Scope  t(computing_timer, "mesh: adapt");
    std::vector<Vector> ghosted(n_fields());
    for (unsigned int b = 0; b < n_fields(); ++b)
      {
        ghosted[b].reinit(operators.locally_owned_dofs,
                          operators.locally_relevant_dofs,
                          mpi_communicator);
        ghosted[b] = solution.block(b);
      }
    NarrowBand::flag_cells_from_phase_field(dof_handler,
                                            ghosted[Field::U],
                                            prm.mesh.band_width,
                                            prm.mesh.finest_level,
                                            prm.mesh.coarsest_level,
                                            options.coarsening_band_factor *
                                              prm.mesh.band_width);
    // smoothing removes flags that cannot be executed (2:1 balance,
    // incomplete sibling groups); keep mesh and factorisation if none is left
    triangulation.prepare_coarsening_and_refinement();
    unsigned int n_flagged = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() &&
          (cell->refine_flag_set() || cell->coarsen_flag_set()))
        ++n_flagged;
    if (Utilities::MPI::sum(n_flagged, mpi_communicator) == 0)
      return;

    parallel::distributed::SolutionTransfer<dim, Vector> transfer(dof_handler);
    std::vector<const Vector *>                          in;
    for (const auto &g : ghosted)
      in.push_back(&g);
    transfer.prepare_for_coarsening_and_refinement(in);
    triangulation.execute_coarsening_and_refinement();

    setup_system();
    std::vector<Vector *> out;
    for (unsigned int b = 0; b < n_fields(); ++b)
      out.push_back(&solution.block(b));
    transfer.interpolate(out);
    if (prm.model.scheme == Scheme::semi_implicit)
      // F^k enters the next step's residual: it must be f_h(U^k) on the
      // new mesh, not an interpolation from the old one
      SemiImplicitScheme<dim>(operators,
                              prm.model.epsilon,
                              prm.model.tau,
                              solution)
        .initialize_f(solution);
    if (options.restoration())
      reset_fixed_u();
    distribute_constraints(solution);
  }



  template <int dim>
  double
  WillmoreProblem<dim>::compute_l2_error(const double time) const
  {
    const double radius = Shapes::exact_radius(prm.geometry, dim, time);
    if (radius < 0)
      return std::numeric_limits<double>::quiet_NaN();
    const Shapes::SphereDistance<dim> distance(
      Shapes::shape_center<dim>(prm.geometry), radius);
    const Shapes::PhaseFieldProfile<dim> exact(distance, prm.model.epsilon);

    Vector u(operators.locally_owned_dofs,
             operators.locally_relevant_dofs,
             mpi_communicator);
    u = solution.block(Field::U);
    dealii::Vector<float> cellwise(triangulation.n_active_cells());
    VectorTools::integrate_difference(
      dof_handler, u, exact, cellwise, QGauss<dim>(3), VectorTools::L2_norm);
    return VectorTools::compute_global_error(triangulation,
                                             cellwise,
                                             VectorTools::L2_norm);
  }



  template <int dim>
  void
  WillmoreProblem<dim>::output_results(const unsigned int step,
                                       const double       time)
  {
    TimerOutput::Scope             t(computing_timer, "output");
    const std::vector<std::string> names =
      prm.model.scheme == Scheme::nested ?
        std::vector<std::string>{"U", "V", "P", "curvature"} :
        std::vector<std::string>{"U", "F", "curvature"};
    std::vector<Vector> fields(names.size());
    for (auto &f : fields)
      f.reinit(operators.locally_owned_dofs,
               operators.locally_relevant_dofs,
               mpi_communicator);
    for (unsigned int b = 0; b < n_fields(); ++b)
      fields[b] = solution.block(b);
    Vector curvature(solution.block(Field::U));
    compute_curvature(curvature);
    fields.back() = curvature;

    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    for (unsigned int i = 0; i < fields.size(); ++i)
      data_out.add_data_vector(fields[i], names[i]);
    dealii::Vector<float> subdomain(triangulation.n_active_cells());
    dealii::Vector<float> level(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          subdomain(cell->active_cell_index()) = cell->subdomain_id();
          level(cell->active_cell_index())     = cell->level();
        }
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.add_data_vector(level, "level");
    data_out.build_patches();
    DataOutBase::VtkFlags flags;
    flags.time  = time;
    flags.cycle = step;
    data_out.set_flags(flags);
    const std::string pvtu = data_out.write_vtu_with_pvtu_record(
      prm.output_directory + "/", "solution", step, mpi_communicator, 5);

    pvd_records.emplace_back(time, pvtu);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::ofstream pvd(prm.output_directory + "/solution.pvd");
        DataOutBase::write_pvd_record(pvd, pvd_records);
      }
  }



  template <int dim>
  void
  WillmoreProblem<dim>::run()
  {
    Timer wall_timer;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::filesystem::create_directories(prm.output_directory);
    MPI_Barrier(mpi_communicator);

    const double h = prm.mesh.h();
    pcout << options.program_name << ": " << dim << "D, "
          << (prm.model.scheme == Scheme::nested ? "nested" : "semi-implicit")
          << " scheme, shape <" << prm.geometry.shape << ">, h = " << h
          << ", epsilon = " << prm.model.epsilon << ", tau = " << prm.model.tau
          << ", inner tau = " << prm.model.inner_tau << ", "
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI rank(s), "
          << (linear_solver->type() == LinearSolverType::direct ?
                "direct (MUMPS)" :
                (prm.model.scheme == Scheme::nested ?
                   "iterative (CG + AMG)" :
                   "iterative (GMRES + AMG)"))
          << " linear solver" << std::endl;
    if (prm.model.scheme == Scheme::nested &&
        prm.model.inner_tau >= 0.5 * std::pow(prm.model.epsilon, 2))
      pcout << "Warning: Inner tau >= epsilon^2/2; the inner (Allen-Cahn) "
               "energy is then not convex and Newton may fail."
            << std::endl;

    create_initial_mesh();
    setup_system();
    initialize_fields();

    StatisticsFile statistics(prm.output_directory + "/statistics.csv",
                              concatenate<std::string>({"step",
                                                        "time",
                                                        "newton_iterations",
                                                        "linear_iterations",
                                                        "cells",
                                                        "dofs",
                                                        "willmore_energy",
                                                        "area_energy",
                                                        "inside_measure",
                                                        "l2_error",
                                                        "wall_seconds",
                                                        "tau",
                                                        "residual_norm"},
                                                       extra_columns()),
                              mpi_communicator);

    const unsigned int n_steps = prm.model.n_ramp_steps + prm.model.n_steps;
    double             time    = 0;
    const auto         record  = [&](const unsigned int step,
                            const StepReport  &report,
                            const double       tau) {
      const Energies e     = compute_energies();
      const double   error = compute_l2_error(time);
      const double   dofs  = double(n_fields()) * dof_handler.n_dofs();
      const double   cells = triangulation.n_global_active_cells();
      statistics.add_row(concatenate<double>({double(step),
                                              time,
                                              double(report.newton_iterations),
                                              double(report.linear_iterations),
                                              cells,
                                              dofs,
                                              e.willmore,
                                              e.area,
                                              e.inside_measure,
                                              error,
                                              wall_timer.wall_time(),
                                              tau,
                                              report.final_residual_norm},
                                             extra_values(e)));
      pcout << "step " << std::setw(4) << step << "  t = " << std::setw(11)
            << std::setprecision(5) << time << "  newton "
            << report.newton_iterations << " (linear "
            << report.linear_iterations << ")  W = " << std::setprecision(7)
            << e.willmore << "  A = " << e.area
            << "  inside = " << e.inside_measure;
      if (!std::isnan(error))
        pcout << "  L2 error = " << std::setprecision(4) << error;
      pcout << "  cells " << cells << "  [" << std::setprecision(3)
            << wall_timer.wall_time() << " s]" << std::endl;
      if (prm.output.vtu_interval > 0 &&
          (step % prm.output.vtu_interval == 0 || step == n_steps))
        output_results(step, time);
    };
    record(0, StepReport(), prm.model.tau);

    // the time step the multiplier P of the current state belongs to
    double state_tau = prm.model.tau;
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        old_solution            = solution;
        const BlockVector saved = solution;
        double            tau   = prm.model.step_size(step);
        StepReport        report;
        const bool        check_energy = prm.model.scheme == Scheme::nested;
        const double      start_energy = check_energy ? weighted_energy() : 0.;
        for (unsigned int attempt = 0;; ++attempt)
          {
            // P is proportional to tau at the start of a step (R_V = 0 with
            // a = tau / ttau^2): start Newton from the P of this tau
            if (prm.model.scheme == Scheme::nested && tau != state_tau)
              solution.block(Field::P) *= tau / state_tau;
            report = solve_time_step(tau);
            if (report.converged)
              break;
            solution = saved;
            AssertThrow(
              attempt < prm.newton.max_step_halvings,
              ExcMessage(
                "Newton's method did not converge in step " +
                std::to_string(step) +
                (attempt == 0 ?
                   std::string(" (retrying with smaller time steps is "
                               "switched off: Newton / Maximum step "
                               "halvings = 0)") :
                   " even after halving the time step " +
                     std::to_string(attempt) + " times") +
                " (tau = " + std::to_string(tau) +
                "). Try a smaller <Time stepping / Tau> or a larger "
                "<Newton / Maximum iterations>. The statistics and output "
                "up to the previous step are complete."));
            tau *= 0.5;
            pcout << "  step " << step
                  << ": Newton failed, retrying with half the time step, "
                     "tau = "
                  << tau << std::endl;
          }
        if (check_energy)
          {
            // thesis Cor. 3.3: on a fixed mesh the minimiser of the outer
            // energy satisfies E^{k+1} + eps |U^{k+1} - U^k|^2 / (2 tau)
            // <= E^k; Newton may converge to another critical point
            const double rise =
              weighted_energy() + dissipation(tau) - start_energy;
            if (prm.output.verbose)
              pcout << "  energy + dissipation - energy before the step: "
                    << std::setprecision(4) << rise << std::endl;
            // round-off of the energies relative to their size (the
            // curvature (U - V) / ttau loses about log10(1/ttau) digits)
            constexpr double energy_roundoff = 1e-10;
            if (rise > energy_roundoff * std::abs(start_energy))
              pcout << "  Warning: step " << step
                    << ": energy + dissipation exceeds the energy before the "
                       "step by "
                    << std::setprecision(4) << rise
                    << " (thesis Cor. 3.3 holds for the minimiser of the "
                       "outer energy, Newton found another critical point)"
                    << std::endl;
          }
        state_tau = tau;
        time += tau;
        record(step, report, tau);
        if (prm.mesh.adaptive && step % prm.mesh.refinement_interval == 0 &&
            step < n_steps)
          {
            const double before =
              options.restoration() ? weighted_energy() : 0.;
            refine_mesh();
            if (options.restoration())
              solve_inner_problem(state_tau);
            if (options.restoration() && prm.output.verbose)
              pcout << std::setprecision(10) << "  re-meshing: weighted energy "
                    << before << " -> " << weighted_energy() << std::endl;
          }
      }
    computing_timer.print_summary();

    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const double peak_megabytes =
      Utilities::MPI::sum(memory.VmHWM / 1024., mpi_communicator);
    pcout << "Peak resident memory, summed over "
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " rank(s): " << std::fixed << std::setprecision(0)
          << peak_megabytes << " MB" << std::defaultfloat << std::endl;
  }



  template class WillmoreProblem<2>;
  template class WillmoreProblem<3>;
} // namespace PhaseField
