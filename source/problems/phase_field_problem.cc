#include <deal.II/base/utilities.h>
#include <phasefield/core/statistics.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/problems/phase_field_problem.h>

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
    settings.scheme               = parameters.model.scheme;
    settings.epsilon              = parameters.model.epsilon;
    settings.inner_tau            = parameters.model.inner_tau;
    settings.outer_energy         = setup.outer_energy;
    settings.newton               = parameters.newton;
    settings.linear_solver        = parameters.linear_solver;
    settings.augmented_lagrangian = parameters.augmented_lagrangian;
    settings.verbose              = parameters.output.verbose;
    scheme = create_time_stepping_scheme<dim>(settings, discretization, pcout);
  }



  template <int dim>
  void
  PhaseFieldProblem<dim>::run()
  {
    create_scheme(prm);
    TimeLoop<dim> time_loop(TimeLoop<dim>::Settings::from(prm),
                            discretization,
                            *scheme,
                            *this,
                            pcout,
                            computing_timer);

    create_output_directory(prm.output_directory, mpi_communicator);
    print_header();
    if (prm.checkpoint.resume)
      time_loop.resume(solution);
    else
      {
        {
          TimerOutput::Scope t(computing_timer, "mesh: initial");
          discretization.create_mesh(setup.signed_distance.get(),
                                     prm.model.epsilon);
        }
        {
          TimerOutput::Scope t(computing_timer, "initialisation");
          initialize_fields();
        }
        time_loop.run(solution);
      }
    computing_timer.print_summary();
    print_peak_memory(pcout, mpi_communicator);
    discretization.print_partition_balance(pcout);
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
    const Shapes::PhaseFieldProfile<dim> u0(*setup.signed_distance,
                                            prm.model.epsilon);
    discretization.interpolate(u0, solution.block(0));
    scheme->initialize(solution, prm.model.tau);
  }



  template class PhaseFieldProblem<2>;
  template class PhaseFieldProblem<3>;
} // namespace PhaseField
