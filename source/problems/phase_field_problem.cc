#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <phasefield/core/constants.h>
#include <phasefield/core/statistics.h>
#include <phasefield/geometry/shapes.h>
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
    discretization_settings(const MeshParameters &mesh,
                            const double          coarsening_band_factor)
    {
      typename Discretization<dim>::Settings settings;
      settings.mesh                   = mesh;
      settings.coarsening_band_factor = coarsening_band_factor;
      return settings;
    }
  } // namespace



  template <int dim>
  PhaseFieldProblem<dim>::PhaseFieldProblem(
    const WillmoreParameters &parameters,
    const Setup              &setup)
    : prm(parameters)
    , level_prm(parameters)
    , setup(setup)
    , mpi_communicator(MPI_COMM_WORLD)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , computing_timer(mpi_communicator,
                      pcout,
                      TimerOutput::never,
                      TimerOutput::wall_times)
    , discretization(discretization_settings<dim>(parameters.mesh,
                                                  setup.coarsening_band_factor),
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
    settings.outer_energy  = setup.outer_energy;
    settings.newton        = parameters.newton;
    settings.linear_solver = parameters.linear_solver;
    settings.verbose       = parameters.output.verbose;
    scheme = create_time_stepping_scheme<dim>(settings, discretization, pcout);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::run()
  {
    create_scheme(prm);
    create_output_directory(prm.output_directory, mpi_communicator);
    print_header();
    BlockVector start;
    if (!prm.checkpoint.resume)
      {
        const unsigned int first_level = prm.start_level();
        if (first_level < prm.mesh.finest_level)
          {
            level_prm = prm.for_finest_level(first_level);
            discretization.start_at_level(first_level);
            create_scheme(level_prm);
          }
        {
          TimerOutput::Scope t(computing_timer, "mesh: initial");
          discretization.create_mesh(setup.signed_distance.get(),
                                     level_prm.model.epsilon);
        }
        {
          TimerOutput::Scope t(computing_timer, "initialisation");
          initialize_fields();
        }
        if (first_level < prm.mesh.finest_level)
          start = coarse_start_value();
      }
    // the scheme of the finest level exists only now
    TimeLoop<dim> time_loop(TimeLoop<dim>::Settings::from(prm,
                                                          setup.program_name),
                            discretization,
                            *scheme,
                            *this,
                            pcout,
                            computing_timer);
    if (prm.checkpoint.resume)
      time_loop.resume(solution);
    else
      time_loop.run(solution, start.n_blocks() > 0 ? &start : nullptr);
    computing_timer.print_summary();
    print_peak_memory(pcout, mpi_communicator);
    discretization.print_partition_balance(pcout);
  }



  template <int dim>
  BlockVector
  PhaseFieldProblem<dim>::coarse_start_value()
  {
    BlockVector start     = solution;
    bool        converged = true;
    for (unsigned int level = level_prm.mesh.finest_level;
         level < prm.mesh.finest_level;
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
    const double       tau = level_prm.model.step_size(1);
    pcout << "Start value of step 1 on level " << level_prm.mesh.finest_level
          << " (h = " << level_prm.mesh.h()
          << ", epsilon = " << level_prm.model.epsilon << ", tau = " << tau
          << ", " << discretization.n_dofs() << " DoFs per field)" << std::endl;
    scheme->prepare_step(start, level_prm.model.tau, tau);
    const StepReport report = this->advance(*scheme, solution, start, tau);
    pcout << "  level " << level_prm.mesh.finest_level << ": "
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
    const WillmoreParameters next = prm.for_finest_level(level);
    const double ratio = level_prm.model.epsilon / next.model.epsilon;
    // the band of the sharpened profile (see ContourProblem::move_to_level())
    discretization.refine_to_level(level, start, 1 / ratio);
    level_prm = next;
    // the mesh of the step resolves the initial data too
    discretization.reinit(solution, scheme->n_fields());
    interpolate_initial_u(solution.block(0));
    discretization.refine_to_band({&solution, &start});
    sharpen_profile(start.block(0), ratio);
    create_scheme(level_prm);
    initialize_fields();
    this->after_remesh(start);
    discretization.distribute_constraints(start);
    scheme->initialize(start, level_prm.model.tau);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::print_header() const
  {
    pcout << setup.program_name << ": " << dim << "D, " << scheme->name()
          << " scheme, shape <" << prm.geometry.shape
          << ">, h = " << prm.mesh.h() << ", epsilon = " << prm.model.epsilon
          << ", tau = " << prm.model.tau
          << ", inner tau = " << prm.model.inner_tau << ", "
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI rank(s), " << scheme->linear_solver_description()
          << " linear solver" << std::endl;
    for (const std::string &warning : scheme->warnings())
      pcout << "Warning: " << warning << std::endl;
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::initialize_fields()
  {
    discretization.reinit(solution, scheme->n_fields());
    interpolate_initial_u(solution.block(0));
    scheme->initialize(solution, level_prm.model.tau);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::interpolate_initial_u(Vector &u) const
  {
    const Shapes::PhaseFieldProfile<dim> u0(*setup.signed_distance,
                                            level_prm.model.epsilon);
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



  template class PhaseFieldProblem<2>;
  template class PhaseFieldProblem<3>;
} // namespace PhaseField
