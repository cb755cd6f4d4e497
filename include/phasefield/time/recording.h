#ifndef phasefield_time_recording_h
#define phasefield_time_recording_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/statistics.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/time/loop_data.h>
#include <phasefield/time/step_size_policy.h>
#include <phasefield/time/time_loop_client.h>
#include <phasefield/time/time_loop_settings.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * What the time loop records of each step: a row of statistics.csv
   * (statistics_columns()), a progress line, and VTU output every
   * `Output / VTU interval` steps and at the last step; in 3D with an
   * `Output / Surface format`, the surface U = 0 at those steps and at the
   * last step (ZeroLevelSurface). The step-size policy's columns
   * (StepSizePolicy::statistics_columns()) follow `step_halvings`, and
   * the progress line shows them with tau.
   */
  template <int dim>
  class StepRecorder
  {
  public:
    StepRecorder(const TimeLoopSettings           &settings,
                 Discretization<dim>              &discretization,
                 TimeSteppingScheme<dim>          &scheme,
                 TimeLoopClient<dim>              &client,
                 const dealii::ConditionalOStream &pcout,
                 dealii::TimerOutput              &timer,
                 LoopData                         &data,
                 const StepSizePolicy             &step_sizes);

    /** Start a new statistics.csv in the output directory. */
    void
    create_statistics();

    /**
     * Continue the statistics.csv of the output directory after its rows
     * up to step @p last_kept_step (StatisticsFile's append mode).
     */
    void
    append_statistics(const unsigned int last_kept_step);

    /**
     * Statistics row, progress line and (if due and @p with_output) VTU
     * output of step @p step with the @p energies of @p state, taken at
     * size @p tau after @p halvings halvings (column `step_halvings`); the
     * energies are kept as LoopData::state_energies. @p last: the run ends
     * with this step (the VTU output is due).
     */
    void
    record(const unsigned int step,
           const BlockVector &state,
           const Energies    &energies,
           const StepReport  &report,
           const double       tau,
           const unsigned int halvings    = 0,
           const bool         with_output = true,
           const bool         last        = false);

  private:
    /**
     * The columns of statistics.csv; record() writes their values in this
     * order.
     */
    std::vector<std::string>
    statistics_columns() const;

    /**
     * The progress line of step @p step with the @p energies, the L2
     * @p error, the client's @p extras, the number of @p cells and, where
     * the step-size policy has columns, the step size @p tau and those.
     */
    void
    print_progress(const unsigned int         step,
                   const Energies            &energies,
                   const StepReport          &report,
                   const double               error,
                   const std::vector<double> &extras,
                   const double               cells,
                   const double               tau) const;

    /** VTU output of the fields and the curvature. */
    void
    output_results(const unsigned int step, const BlockVector &state);

    /**
     * Is the surface file of step @p step due: in 3D with a surface
     * format, at the VTU output steps and at the last step (@p last: the
     * run ends with this step)?
     */
    bool
    surface_due(const unsigned int step, const bool last) const;

    /**
     * Write the surface U = 0 of @p state as surface_<step>.<format> into
     * the output directory and print its size (3D only).
     */
    void
    write_surface(const unsigned int step, const BlockVector &state);

    const TimeLoopSettings           &settings;
    Discretization<dim>              &discretization;
    TimeSteppingScheme<dim>          &scheme;
    TimeLoopClient<dim>              &client;
    const dealii::ConditionalOStream &pcout;
    dealii::TimerOutput              &timer;
    LoopData                         &data;
    const StepSizePolicy             &step_sizes;
    dealii::Timer                     wall_timer;
    std::unique_ptr<StatisticsFile>   statistics;
  };
} // namespace PhaseField

#endif
