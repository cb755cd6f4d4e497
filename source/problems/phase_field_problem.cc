#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <phasefield/core/block_vector_tools.h>
#include <phasefield/core/constants.h>
#include <phasefield/core/statistics.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/problems/initial_shape_check.h>
#include <phasefield/problems/phase_field_problem.h>
#include <phasefield/schemes/scheme_registry.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** The discretisation of the Willmore-flow parameters. */
    template <int dim>
    typename Discretization<dim>::Settings
    discretization_settings(const WillmoreParameters &parameters,
                            const typename PhaseFieldProblem<dim>::Setup &setup)
    {
      const MeshParameters                  &mesh = parameters.mesh;
      typename Discretization<dim>::Settings settings;
      settings.mesh   = mesh;
      settings.solver = resolve_solver_choice(parameters.linear_solver,
                                              parameters.model.scheme.name,
                                              dim);
      settings.mesh.finest_level =
        std::max(mesh.finest_level, setup.finest_level);
      settings.coarsening_band_factor = setup.coarsening_band_factor;
      return settings;
    }
  } // namespace



  template <int dim>
  PhaseFieldProblem<dim>::PhaseFieldProblem(
    const WillmoreParameters &parameters,
    const Setup              &setup)
    : willmore_parameters(parameters)
    , level_parameters(parameters)
    , setup(setup)
    , mpi_communicator(MPI_COMM_WORLD)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , computing_timer(mpi_communicator,
                      pcout,
                      TimerOutput::never,
                      TimerOutput::wall_times)
    , discretization(discretization_settings<dim>(parameters, setup),
                     mpi_communicator)
  {}



  template <int dim>
  void
  PhaseFieldProblem<dim>::create_scheme(const WillmoreParameters &parameters)
  {
    SchemeSettings settings;
    settings.scheme        = parameters.model.scheme;
    settings.epsilon       = parameters.model.epsilon;
    settings.inner_tau     = parameters.model.inner_tau;
    settings.outer_energy  = scheme_outer_energy();
    settings.newton        = parameters.newton;
    settings.linear_solver = parameters.linear_solver;
    settings.solver        = discretization.get_settings().solver;
    settings.verbose       = parameters.output.verbose;
    scheme = create_time_stepping_scheme<dim>(settings, discretization, pcout);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::run()
  {
    const unsigned int finest_level =
      discretization.get_settings().mesh.finest_level;
    if (setup.signed_distance)
      check_initial_shape(*setup.signed_distance,
                          willmore_parameters,
                          willmore_parameters.for_finest_level(finest_level));
    create_output_directory(willmore_parameters.output_directory,
                            mpi_communicator);
    set_first_level();
    // a run that refines to finer levels later (Setup::finest_level)
    // starts its mesh, or loads its checkpoint, on the first level
    const unsigned int first_level = level_parameters.mesh.finest_level;
    if (first_level < discretization.get_settings().mesh.finest_level)
      discretization.start_at_level(first_level);
    create_scheme(level_parameters);
    print_header();
    if (!willmore_parameters.checkpoint.resume)
      create_initial_state();
    run_time_loops();
    computing_timer.print_summary();
    print_peak_memory(pcout, mpi_communicator);
    discretization.print_memory_by_item(pcout);
    discretization.print_partition_balance(pcout);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::set_first_level()
  {
    level_parameters = willmore_parameters;
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::create_initial_state()
  {
    const unsigned int first_level = level_parameters.start_level();
    if (first_level < level_parameters.mesh.finest_level)
      {
        level_parameters = level_parameters.for_finest_level(first_level);
        discretization.start_at_level(first_level);
        create_scheme(level_parameters);
      }
    {
      TimerOutput::Scope t(computing_timer, "mesh: initial");
      discretization.create_mesh(setup.signed_distance.get(),
                                 level_parameters.model.epsilon);
    }
    TimerOutput::Scope t(computing_timer, "initialisation");
    initialize_fields();
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::run_time_loops()
  {
    BlockVector start;
    if (!willmore_parameters.checkpoint.resume &&
        level_parameters.mesh.finest_level <
          willmore_parameters.mesh.finest_level)
      start = coarse_start_value();
    // the scheme of the finest level exists only now
    TimeLoop<dim> time_loop(time_loop_settings(willmore_parameters),
                            discretization,
                            *scheme,
                            *this,
                            pcout,
                            computing_timer);
    if (willmore_parameters.checkpoint.resume)
      time_loop.resume(solution);
    else
      time_loop.run(solution, start.n_blocks() > 0 ? &start : nullptr);
  }



  template <int dim>
  typename TimeLoop<dim>::Settings
  PhaseFieldProblem<dim>::time_loop_settings(
    const WillmoreParameters &parameters) const
  {
    typename TimeLoop<dim>::Settings settings =
      TimeLoop<dim>::Settings::from(parameters, setup.program_name);
    const Checkpoint::Parameters own = own_checkpoint_parameters();
    settings.checkpoint_parameters.insert(settings.checkpoint_parameters.end(),
                                          own.begin(),
                                          own.end());
    return settings;
  }



  template <int dim>
  BlockVector
  PhaseFieldProblem<dim>::coarse_start_value()
  {
    BlockVector start     = solution;
    bool        converged = true;
    for (unsigned int level = level_parameters.mesh.finest_level;
         level < willmore_parameters.mesh.finest_level;
         ++level)
      {
        // after a failure the levels are still passed through: the mesh
        // of step 1 is refined from the coarse one
        converged = converged && solve_coarse_step(start);
        if (!converged)
          start = solution;
        move_start_to_level(level + 1, start);
      }
    if (converged)
      return start;
    pcout << "Step 1 starts from the initial data: a coarse step did not "
             "converge"
          << std::endl;
    return BlockVector();
  }



  template <int dim>
  bool
  PhaseFieldProblem<dim>::solve_coarse_step(BlockVector &start)
  {
    TimerOutput::Scope t(computing_timer, "start value: coarse steps");
    Timer              timer;
    const double       tau = level_parameters.model.step_size(1);
    pcout << "Start value of step 1 on level "
          << level_parameters.mesh.finest_level
          << " (h = " << level_parameters.mesh.h()
          << ", epsilon = " << level_parameters.model.epsilon
          << ", tau = " << tau << ", " << discretization.n_dofs()
          << " DoFs per field)" << std::endl;
    const StepReport report = this->prepared_advance(
      *scheme, solution, start, level_parameters.model.tau, tau);
    pcout << "  level " << level_parameters.mesh.finest_level << ": "
          << report.newton_iterations << " Newton, " << report.linear_iterations
          << " linear iterations, " << timer.wall_time() << " s"
          << (report.converged ? "" : ", not converged") << std::endl;
    return report.converged;
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::move_start_to_level(const unsigned int level,
                                              BlockVector       &start)
  {
    TimerOutput::Scope t(computing_timer, "start value: level transition");
    const WillmoreParameters next = willmore_parameters.for_finest_level(level);
    const double ratio = level_parameters.model.epsilon / next.model.epsilon;
    // the band of the sharpened profile (see ContourProblem::move_to_level())
    refine_u_to_level(level, start, 1 / ratio);
    level_parameters = next;
    // the mesh of the step resolves the initial data too
    discretization.reinit(solution, scheme->n_fields());
    interpolate_initial_u(solution.block(0));
    discretization.refine_to_band({&solution, &start});
    sharpen_profile(start.block(0), ratio);
    create_scheme(level_parameters);
    initialize_fields();
    this->after_remesh(start);
    discretization.distribute_constraints(start);
    scheme->initialize(start, level_parameters.model.tau);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::print_header() const
  {
    pcout << setup.program_name << ": " << dim << "D, " << scheme->name()
          << " scheme, shape <" << willmore_parameters.geometry.shape
          << ">, h = " << willmore_parameters.mesh.h()
          << ", epsilon = " << willmore_parameters.model.epsilon
          << ", tau = " << willmore_parameters.model.tau
          << ", inner tau = " << willmore_parameters.model.inner_tau << ", "
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI rank(s), " << scheme->linear_solver_description()
          << " linear solver" << std::endl;
    std::vector<std::string> warnings = scheme->warnings();
    const std::string        epsilon =
      epsilon_resolution_warning(willmore_parameters.for_finest_level(
        discretization.get_settings().mesh.finest_level));
    if (!epsilon.empty())
      warnings.push_back(epsilon);
    for (const std::string &warning : warnings)
      pcout << "Warning: " << warning << std::endl;
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::initialize_fields()
  {
    discretization.reinit(solution, scheme->n_fields());
    interpolate_initial_u(solution.block(0));
    scheme->initialize(solution, level_parameters.model.tau);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::interpolate_initial_u(Vector &u) const
  {
    const Shapes::PhaseFieldProfile<dim> u0(*setup.signed_distance,
                                            level_parameters.model.epsilon);
    discretization.interpolate(u0, u);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::sharpen_profile(Vector &u, const double ratio)
  {
    // U = tanh(d/eps_old) gives d/eps_old = artanh(U); |U| = 1 (or beyond,
    // from the interpolation) is clamped to keep artanh finite
    const double largest = 1 - Constants::roundoff;
    for (double &value : u)
      value =
        std::tanh(ratio * std::atanh(std::clamp(value, -largest, largest)));
    u.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::refine_u_to_level(const unsigned int level,
                                            BlockVector       &state,
                                            const double       band_scale)
  {
    const unsigned int n_fields = state.n_blocks();
    BlockVector        u        = take_blocks(state, {0});
    // the other fields of the coarse mesh are freed before the transfer
    state.reinit(0);
    discretization.refine_to_level(level, u, band_scale);
    discretization.reinit(state, n_fields);
    swap_into({0}, u, state);
  }



  template class PhaseFieldProblem<2>;
  template class PhaseFieldProblem<3>;
} // namespace PhaseField
