#include <cmath>
#include <deal.II/base/exceptions.h>
#include <iomanip>
#include <phasefield/mesh/zero_level_surface.h>
#include <phasefield/schemes/energy_term_registry.h>
#include <phasefield/time/finite_fields.h>
#include <phasefield/time/recording.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** @p head followed by each of @p tails. */
    template <typename T, typename... Tails>
    std::vector<T>
    concatenate(std::vector<T> head, const Tails &...tails)
    {
      (head.insert(head.end(), tails.begin(), tails.end()), ...);
      return head;
    }
  } // namespace



  template <int dim>
  StepRecorder<dim>::StepRecorder(const TimeLoopSettings   &settings,
                                  Discretization<dim>      &discretization,
                                  TimeSteppingScheme<dim>  &scheme,
                                  TimeLoopClient<dim>      &client,
                                  const ConditionalOStream &pcout,
                                  TimerOutput              &timer,
                                  LoopData                 &data,
                                  const StepSizePolicy     &step_sizes)
    : settings(settings)
    , discretization(discretization)
    , scheme(scheme)
    , client(client)
    , pcout(pcout)
    , timer(timer)
    , data(data)
    , step_sizes(step_sizes)
  {}



  template <int dim>
  void
  StepRecorder<dim>::create_statistics()
  {
    statistics =
      std::make_unique<StatisticsFile>(settings.output_directory +
                                         "/statistics.csv",
                                       statistics_columns(),
                                       discretization.get_mpi_communicator());
  }



  template <int dim>
  void
  StepRecorder<dim>::append_statistics(const unsigned int last_kept_step)
  {
    statistics =
      std::make_unique<StatisticsFile>(settings.output_directory +
                                         "/statistics.csv",
                                       statistics_columns(),
                                       discretization.get_mpi_communicator(),
                                       last_kept_step);
  }



  template <int dim>
  std::vector<std::string>
  StepRecorder<dim>::statistics_columns() const
  {
    return concatenate<std::string>({"step",
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
                                    scheme.statistics_columns(),
                                    std::vector<std::string>{"step_halvings"},
                                    step_sizes.statistics_columns(),
                                    energy_term_columns(client.outer_energy()),
                                    client.extra_columns());
  }



  template <int dim>
  void
  StepRecorder<dim>::record(const unsigned int step,
                            const BlockVector &state,
                            const Energies    &e,
                            const StepReport  &report,
                            const double       tau,
                            const unsigned int halvings,
                            const bool         with_output,
                            const bool         last)
  {
    data.state_energies = e;
    const double error  = client.l2_error(state, data.time);
    const double dofs   = double(scheme.n_fields()) * discretization.n_dofs();
    const double cells =
      discretization.get_triangulation().n_global_active_cells();
    // no NaN in statistics.csv or the VTU output: stop before writing
    AssertThrow(std::isfinite(e.willmore) && std::isfinite(e.area) &&
                  std::isfinite(e.inside_measure),
                ExcMessage("Step " + std::to_string(step) +
                           ": an energy or the inside measure is not finite "
                           "(Willmore " +
                           std::to_string(e.willmore) + ", area " +
                           std::to_string(e.area) + ", inside " +
                           std::to_string(e.inside_measure) +
                           "); nothing of this step was written. Try a "
                           "smaller <Time stepping / Tau>."));
    const std::vector<double> extras = client.extra_values(state, e);
    statistics->add_row(
      concatenate<double>({double(step),
                           data.time,
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
                          report.counts_of(scheme.statistics_columns()),
                          std::vector<double>{double(halvings)},
                          step_sizes.statistics_values(),
                          energy_term_values(client.outer_energy(),
                                             discretization.get_operators(),
                                             state.block(0)),
                          extras));
    print_progress(step, e, report, error, extras, cells, tau);
    if (with_output && settings.vtu_interval > 0 &&
        (step % settings.vtu_interval == 0 || step == data.final_step || last))
      output_results(step, state);
    if (with_output && surface_due(step, last))
      write_surface(step, state);
  }



  template <int dim>
  void
  StepRecorder<dim>::print_progress(const unsigned int         step,
                                    const Energies            &e,
                                    const StepReport          &report,
                                    const double               error,
                                    const std::vector<double> &extras,
                                    const double               cells,
                                    const double               tau) const
  {
    pcout << "step " << std::setw(4) << step << "  t = " << std::setw(11)
          << std::setprecision(5) << data.time << "  newton "
          << report.newton_iterations << " (linear " << report.linear_iterations
          << ")  W = " << std::setprecision(7) << e.willmore
          << "  A = " << e.area << "  inside = " << e.inside_measure;
    if (!std::isnan(error))
      pcout << "  L2 error = " << std::setprecision(4) << error;
    const std::vector<std::string> extra_names = client.extra_columns();
    for (unsigned int i = 0; i < extras.size(); ++i)
      pcout << "  " << extra_names[i] << " = " << std::setprecision(5)
            << extras[i];
    const std::vector<std::string> policy_names =
      step_sizes.statistics_columns();
    if (!policy_names.empty())
      pcout << "  tau = " << std::setprecision(4) << tau;
    const std::vector<double> policy_values = step_sizes.statistics_values();
    for (unsigned int i = 0; i < policy_names.size(); ++i)
      pcout << "  " << policy_names[i] << " = " << std::setprecision(3)
            << policy_values[i];
    pcout << "  cells " << cells << "  [" << std::setprecision(3)
          << wall_timer.wall_time() << " s]" << std::endl;
  }



  template <int dim>
  void
  StepRecorder<dim>::output_results(const unsigned int step,
                                    const BlockVector &state)
  {
    TimerOutput::Scope t(timer, "output");
    Vector             curvature(state.block(0));
    scheme.curvature(state, curvature);
    const std::vector<std::string> names = scheme.field_names();
    std::vector<std::pair<std::string, const Vector *>> fields;
    for (unsigned int b = 0; b < names.size(); ++b)
      fields.emplace_back(names[b], &state.block(b));
    fields.emplace_back("curvature", &curvature);
    check_output_fields_finite(step, fields);
    discretization.write_output(settings.output_directory,
                                step,
                                data.time,
                                fields);
  }



  template <int dim>
  bool
  StepRecorder<dim>::surface_due(const unsigned int step, const bool last) const
  {
    return dim == 3 && settings.surface_format != SurfaceFormat::none &&
           (step == data.final_step || last ||
            (settings.vtu_interval > 0 && step % settings.vtu_interval == 0));
  }



  template <int dim>
  void
  StepRecorder<dim>::write_surface(const unsigned int step,
                                   const BlockVector &state)
  {
    if constexpr (dim == 3)
      {
        TimerOutput::Scope     t(timer, "output: surface");
        constexpr unsigned int n_digits = 5;
        const std::string      name =
          "surface_" + Utilities::int_to_string(step, n_digits) + "." +
          ZeroLevelSurface::extension(settings.surface_format);
        // the continuous Q1 field: hanging nodes on their constraints
        Vector u = state.block(0);
        discretization.get_constraints().distribute(u);
        const ZeroLevelSurface::Summary surface =
          ZeroLevelSurface::write(discretization.get_dof_handler(),
                                  discretization.ghosted_copy(u),
                                  settings.surface_format,
                                  settings.output_directory + "/" + name);
        pcout << "  " << name << ": " << surface.n_triangles
              << " triangles, area " << std::setprecision(6) << surface.area
              << ", enclosed volume " << surface.volume << std::endl;
      }
    else
      {
        (void)step;
        (void)state;
      }
  }



  template class StepRecorder<2>;
  template class StepRecorder<3>;
} // namespace PhaseField
