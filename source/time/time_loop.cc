#include <cmath>
#include <deal.II/base/exceptions.h>
#include <phasefield/time/checkpoint.h>
#include <phasefield/time/time_loop.h>
#include <string>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * Relative round-off of the time: a run is at its end time within it,
     * so that summed step sizes end there, not in a sliver step after it.
     */
    constexpr double time_roundoff = 1e-12;
  } // namespace



  template <int dim>
  TimeLoop<dim>::TimeLoop(const Settings           &settings,
                          Discretization<dim>      &discretization,
                          TimeSteppingScheme<dim>  &scheme,
                          Client                   &client,
                          const ConditionalOStream &pcout,
                          TimerOutput              &timer)
    : settings(settings)
    , discretization(discretization)
    , scheme(scheme)
    , client(client)
    , pcout(pcout)
    , n_steps(settings.n_steps())
    , step_sizes(create_step_size_policy(
        this->settings,
        [this](const double scheduled) {
          return this->client.next_step_size(scheduled);
        },
        discretization.get_operators().lumped_mass))
    , step_attempt(this->settings,
                   scheme,
                   client,
                   pcout,
                   timer,
                   data,
                   *step_sizes)
    , remeshing(this->settings,
                discretization,
                scheme,
                client,
                pcout,
                timer,
                data,
                *step_sizes,
                step_attempt)
    , recorder(this->settings,
               discretization,
               scheme,
               client,
               pcout,
               timer,
               data,
               *step_sizes)
    , checkpointing(this->settings,
                    discretization,
                    scheme,
                    client,
                    pcout,
                    timer,
                    data,
                    *step_sizes,
                    remeshing)
  {
    if (settings.model.step_control.stationary_tolerance > 0 &&
        !scheme.has_energy_law())
      throw InputError("<Time stepping / Stationary tolerance> needs a scheme "
                       "with an energy law (nested, augmented lagrangian); "
                       "the " +
                       scheme.name() + " scheme has none.");
    data.final_step = n_steps;
  }



  template <int dim>
  void
  TimeLoop<dim>::run(BlockVector &state, const BlockVector *first_start_value)
  {
    // checkpoints of an earlier run do not belong to this one
    Checkpoint::remove_all(settings.output_directory,
                           discretization.get_mpi_communicator());
    recorder.create_statistics();
    recorder.record(0,
                    state,
                    data.energies_of(scheme, state),
                    StepReport(),
                    settings.model.tau);
    run_steps(1, state, first_start_value);
  }



  template <int dim>
  void
  TimeLoop<dim>::resume(BlockVector &state)
  {
    last_step = checkpointing.load_checkpoint(state);
    if (last_step >= data.final_step && settings.refuse_empty_resume)
      throw InputError(
        "<Checkpoint / Resume> = true, but the last checkpoint in <" +
        settings.output_directory + "> is after step " +
        std::to_string(last_step) + ", and this run ends with step " +
        std::to_string(data.final_step) +
        " (<Time stepping / Number of steps> plus <Ramp-up steps>, or the "
        "step at which <Stationary tolerance> ended it; shape_from_contour: "
        "the steps of its last level): there is no step to take. Raise "
        "<Time stepping / Number of steps> (shape_from_contour: the last "
        "entry of <Multilevel / Steps per level>) to continue the run.");
    if (reached_end_time())
      throw InputError("<Checkpoint / Resume> = true, but the last checkpoint "
                       "in <" +
                       settings.output_directory +
                       "> is at t = " + std::to_string(data.time) +
                       ", at or after <Time stepping / End time> = " +
                       std::to_string(settings.model.step_control.end_time) +
                       ": there is no step to take. Raise <End time> to "
                       "continue the run.");
    recorder.append_statistics(last_step);
    pcout << "resuming after step " << last_step << " at t = " << data.time
          << std::endl;
    run_steps(last_step + 1, state);
  }



  template <int dim>
  void
  TimeLoop<dim>::continue_run(BlockVector       &state,
                              const unsigned int previous_step,
                              const double       start_time)
  {
    data.step_offset = previous_step;
    data.final_step  = previous_step + n_steps;
    last_step        = previous_step;
    data.time        = start_time;
    recorder.append_statistics(previous_step);
    recorder.record(previous_step,
                    state,
                    data.energies_of(scheme, state),
                    StepReport(),
                    settings.model.tau,
                    0,
                    false);
    run_steps(previous_step + 1, state);
  }



  template <int dim>
  void
  TimeLoop<dim>::run_steps(const unsigned int first_step,
                           BlockVector       &state,
                           const BlockVector *first_start_value)
  {
    for (unsigned int step = first_step; step <= data.final_step; ++step)
      {
        data.old_state    = state;
        data.old_energies = data.energies_of(scheme, state);
        const double tried_tau =
          within_end_time(step_sizes->first_step_size(step - data.step_offset));
        typename StepAttempt<dim>::Attempt attempt{tried_tau, false};
        if (step == first_step && first_start_value != nullptr)
          state = *first_start_value;
        else
          attempt = step_attempt.predict_start_value(step, state, tried_tau);
        const typename StepAttempt<dim>::Result result =
          remeshing.advance_on_resolving_mesh(step, state, attempt);
        const bool ends = accept_step(step, state, result, tried_tau);
        // asked after every step, the last one too: the client may keep
        // a history that a checkpoint of this step holds
        const bool client_finished =
          client.finished(step, state, result.energies);
        const bool finished =
          step == data.final_step || client_finished || ends;
        const bool checkpoint_written = end_step(step, state, finished);
        if (finished)
          break;
        checkpointing.stop_if_requested(step, state, checkpoint_written);
      }
  }



  template <int dim>
  bool
  TimeLoop<dim>::accept_step(const unsigned int                       step,
                             const BlockVector                       &state,
                             const typename StepAttempt<dim>::Result &result,
                             const double                             tried_tau)
  {
    data.changed_on_resume = false;
    const double tau       = result.tau;
    if (step_attempt.extrapolates())
      data.predictor.record(data.old_state,
                            state,
                            tau,
                            scheme.start_extrapolation());
    step_sizes->accept(tau, tried_tau, data.old_state, state);
    client.step_accepted(step,
                         data.old_state,
                         data.old_energies,
                         state,
                         result.energies,
                         result.report,
                         tau,
                         tried_tau);
    data.time += tau;
    last_step = step;
    // tau = tried_tau / 2^halvings exactly
    const auto halvings =
      static_cast<unsigned int>(std::lround(std::log2(tried_tau / tau)));
    const bool ends =
      reached_end_time() || stationary(step, state, result.energies, tau);
    recorder.record(
      step, state, result.energies, result.report, tau, halvings, true, ends);
    return ends;
  }



  template <int dim>
  bool
  TimeLoop<dim>::end_step(const unsigned int step,
                          BlockVector       &state,
                          const bool         finished)
  {
    const unsigned int checkpoints = settings.checkpoint_interval;
    // a checkpoint holds the start of the next step: after the last
    // step too, the mesh is adapted for it
    const bool checkpoint = checkpoints > 0 && step % checkpoints == 0;
    if (settings.adaptive && step % settings.refinement_interval == 0 &&
        (!finished || checkpoint))
      remeshing.remesh(state);
    if (checkpoint)
      checkpointing.write_checkpoint(step, state, finished);
    return checkpoint;
  }



  template <int dim>
  double
  TimeLoop<dim>::within_end_time(const double tau) const
  {
    const double end_time = settings.model.step_control.end_time;
    if (end_time > 0 && data.time + tau >= end_time * (1 - time_roundoff))
      return end_time - data.time;
    return tau;
  }



  template <int dim>
  bool
  TimeLoop<dim>::reached_end_time() const
  {
    const double end_time = settings.model.step_control.end_time;
    return end_time > 0 && data.time >= end_time * (1 - time_roundoff);
  }



  template <int dim>
  bool
  TimeLoop<dim>::stationary(const unsigned int step,
                            const BlockVector &state,
                            const Energies    &energies,
                            const double       tau) const
  {
    const double tolerance = settings.model.step_control.stationary_tolerance;
    if (!(tolerance > 0))
      return false;
    const double before =
      client.stationarity_energy(scheme, data.old_state, data.old_energies);
    const double after = client.stationarity_energy(scheme, state, energies);
    const double rate  = std::abs(after - before) / (tau * std::abs(after));
    if (!(rate < tolerance))
      return false;
    pcout << "stationary after step " << step << " at t = " << data.time
          << ": the energy changes by " << rate
          << " of itself per unit time, below <Time stepping / Stationary "
             "tolerance> = "
          << tolerance << "; the run ends here" << std::endl;
    return true;
  }



  template class TimeLoop<2>;
  template class TimeLoop<3>;
} // namespace PhaseField
