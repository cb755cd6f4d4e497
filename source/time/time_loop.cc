#include <cmath>
#include <deal.II/base/exceptions.h>
#include <iomanip>
#include <limits>
#include <numeric>
#include <optional>
#include <phasefield/core/block_vector_tools.h>
#include <phasefield/core/stop_request.h>
#include <phasefield/schemes/energy_term_registry.h>
#include <phasefield/time/checkpoint.h>
#include <phasefield/time/finite_fields.h>
#include <phasefield/time/time_loop.h>
#include <sstream>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * Whether @p a and @p b (the same layout) hold the same values on
     * every rank: collective (deal.II's operator== compares the locally
     * owned values only).
     */
    bool
    same_values(const BlockVector &a, const BlockVector &b)
    {
      return Utilities::MPI::min(a == b ? 1 : 0,
                                 a.block(0).get_mpi_communicator()) == 1;
    }

    /** @p head followed by each of @p tails. */
    template <typename T, typename... Tails>
    std::vector<T>
    concatenate(std::vector<T> head, const Tails &...tails)
    {
      (head.insert(head.end(), tails.begin(), tails.end()), ...);
      return head;
    }

    /**
     * The message of step @p step of the scheme @p scheme_name that failed
     * (@p failure says why) after @p attempt halvings.
     */
    std::string
    step_failure_message(const std::string &failure,
                         const std::string &scheme_name,
                         const unsigned int step,
                         const unsigned int attempt,
                         const double       tau)
    {
      return "Step " + std::to_string(step) + ": " + failure +
             (attempt == 0 ?
                std::string(" (retrying with smaller time steps is "
                            "switched off: Newton / Maximum step "
                            "halvings = 0)") :
                " even after halving the time step " + std::to_string(attempt) +
                  " times") +
             " (tau = " + std::to_string(tau) +
             "). Try a smaller <Time stepping / Tau> or larger iteration "
             "limits (<Newton / Maximum iterations>, <Linear solver / "
             "Maximum iterations>; for the augmented lagrangian scheme the "
             "limits in subsection <Augmented Lagrangian>). The " +
             scheme_name +
             " scheme's statistics and output up to the previous step are "
             "complete.";
    }
  } // namespace



  template <int dim>
  void
  TimeLoop<dim>::check_time(const Checkpoint::State &saved,
                            const std::string       &path) const
  {
    // the scheduled sizes are the largest a step takes
    double longest = 0;
    for (unsigned int step = 1; step <= saved.step; ++step)
      longest += settings.largest_step_factor * settings.model.step_size(step);
    constexpr double roundoff = 1e-12;
    if (saved.time <= longest * (1 + roundoff))
      return;
    throw InputError("The checkpoint <" + path + "> is after step " +
                     std::to_string(saved.step) + " at time " +
                     std::to_string(saved.time) + ", later than " +
                     std::to_string(longest) +
                     ", which steps of <Time stepping / Tau> (and the ramp-up) "
                     "reach: its state.txt is damaged, or <Time stepping / "
                     "Tau> is not that of the run that wrote it.");
  }



  template <int dim>
  typename TimeLoop<dim>::Settings
  TimeLoop<dim>::Settings::from(const WillmoreParameters &parameters,
                                const std::string        &program_name)
  {
    Settings s;
    s.model                    = parameters.model;
    s.max_step_halvings        = parameters.newton.max_step_halvings;
    s.max_inside_change_factor = parameters.model.max_inside_change_factor;
    s.regrow_step_size         = parameters.newton.regrow_step_size;
    s.adaptive                 = parameters.mesh.adaptive;
    s.refinement_interval      = parameters.mesh.refinement_interval;
    s.vtu_interval             = parameters.output.vtu_interval;
    s.verbose                  = parameters.output.verbose;
    s.output_directory         = parameters.output_directory;
    s.checkpoint_interval      = parameters.checkpoint.interval;
    s.extrapolated_start       = parameters.model.extrapolated_start;
    s.allowed_changes          = parameters.checkpoint.allowed_changes;
    s.checkpoint_parameters    = {
         {"Program", program_name},
         {"Dimension", std::to_string(parameters.dimension)},
         {"Mesh / Finest level", std::to_string(parameters.mesh.finest_level)},
         {"Mesh / Coarsest level", std::to_string(parameters.mesh.coarsest_level)},
         {"Mesh / Adaptive", parameters.mesh.adaptive ? "true" : "false"},
         {"Phase field / Epsilon",
          Checkpoint::exact_value(parameters.model.epsilon)},
         {"Time stepping / Scheme", parameters.model.scheme.name},
         {"Time stepping / Inner tau",
          Checkpoint::exact_value(parameters.model.inner_tau)}};
    return s;
  }



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
    , timer(timer)
    , n_steps(settings.model.n_ramp_steps + settings.model.n_steps)
    , final_step(n_steps)
    , state_tau(settings.model.tau)
  {
    scheme_before_remesh = discretization.get_triangulation()
                             .signals.pre_distributed_refinement.connect(
                               [this]() { this->scheme.before_remesh(); });
  }



  template <int dim>
  std::vector<std::string>
  TimeLoop<dim>::statistics_columns() const
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
                                    energy_term_columns(client.outer_energy()),
                                    client.extra_columns());
  }



  template <int dim>
  void
  TimeLoop<dim>::run(BlockVector &state, const BlockVector *first_start_value)
  {
    // checkpoints of an earlier run do not belong to this one
    Checkpoint::remove_all(settings.output_directory,
                           discretization.get_mpi_communicator());
    statistics =
      std::make_unique<StatisticsFile>(settings.output_directory +
                                         "/statistics.csv",
                                       statistics_columns(),
                                       discretization.get_mpi_communicator());
    record(0, state, energies_of(state), StepReport(), settings.model.tau);
    run_steps(1, state, first_start_value);
  }



  template <int dim>
  void
  TimeLoop<dim>::resume(BlockVector &state)
  {
    last_step = load_checkpoint(state);
    if (last_step >= final_step && settings.refuse_empty_resume)
      throw InputError(
        "<Checkpoint / Resume> = true, but the last checkpoint in <" +
        settings.output_directory + "> is after step " +
        std::to_string(last_step) + ", and this run ends with step " +
        std::to_string(final_step) +
        " (<Time stepping / Number of steps> plus <Ramp-up steps>): there is "
        "no step to take. Raise <Time stepping / Number of steps> to continue "
        "the run.");
    statistics =
      std::make_unique<StatisticsFile>(settings.output_directory +
                                         "/statistics.csv",
                                       statistics_columns(),
                                       discretization.get_mpi_communicator(),
                                       last_step);
    pcout << "resuming after step " << last_step << " at t = " << time
          << std::endl;
    run_steps(last_step + 1, state);
  }



  template <int dim>
  void
  TimeLoop<dim>::continue_run(BlockVector       &state,
                              const unsigned int previous_step,
                              const double       start_time)
  {
    step_offset = previous_step;
    final_step  = previous_step + n_steps;
    last_step   = previous_step;
    time        = start_time;
    statistics =
      std::make_unique<StatisticsFile>(settings.output_directory +
                                         "/statistics.csv",
                                       statistics_columns(),
                                       discretization.get_mpi_communicator(),
                                       previous_step);
    record(previous_step,
           state,
           energies_of(state),
           StepReport(),
           settings.model.tau,
           0,
           false);
    run_steps(previous_step + 1, state);
  }



  template <int dim>
  unsigned int
  TimeLoop<dim>::load_checkpoint(BlockVector &state)
  {
    TimerOutput::Scope t(timer, "checkpoint: load");
    const MPI_Comm     comm = discretization.get_mpi_communicator();
    const std::string  path =
      Checkpoint::find_last(settings.output_directory, comm);
    // before p4est or anything else reads the files
    changed_on_resume = Checkpoint::verify(path,
                                           settings.checkpoint_parameters,
                                           settings.allowed_changes,
                                           comm);
    if (changed_on_resume && scheme.has_energy_law())
      pcout << "The energy law is not checked in the first step after the "
               "checkpoint: its state belongs to the parameters it was "
               "written with."
            << std::endl;
    const Checkpoint::State saved = Checkpoint::read_state(path, comm);
    if (saved.step_offset == 0)
      check_time(saved, path);
    if (saved.n_fields != scheme.n_fields())
      throw InputError("The checkpoint <" + path + "> has " +
                       std::to_string(saved.n_fields) +
                       " fields, but the scheme <" + scheme.name() + "> has " +
                       std::to_string(scheme.n_fields()) +
                       " (<Time stepping / Scheme> must be that of the run "
                       "that wrote it).");
    BlockVector stored(saved.n_stored_fields);
    discretization.load(Checkpoint::mesh_filename(path), stored);
    discretization.reinit(state, saved.n_fields);
    const bool restores = saved.n_stored_fields < saved.n_fields;
    const std::vector<unsigned int> blocks =
      restores ? carried_blocks(saved.n_fields) : all_blocks(saved.n_fields);
    if (blocks.size() != saved.n_stored_fields)
      throw InputError("The checkpoint <" + path + "> holds " +
                       std::to_string(saved.n_stored_fields) + " of the " +
                       std::to_string(saved.n_fields) +
                       " fields, but the scheme <" + scheme.name() +
                       "> restores the others only with " +
                       std::to_string(blocks.size()) + " stored.");
    swap_into(blocks, stored, state);
    discretization.reinit(old_state, saved.n_fields);
    discretization.set_pvd_records(saved.pvd_records);
    time            = saved.time;
    state_tau       = saved.state_tau;
    step_size_limit = saved.step_size_limit;
    step_offset     = saved.step_offset;
    final_step      = saved.finished ? saved.step : step_offset + n_steps;
    client.after_load(state, saved.problem_data);
    state_energies.reset();
    scheme.reset_solver();
    if (restores)
      {
        scheme.after_remesh(state, state_tau);
        discretization.distribute_constraints(state);
      }
    // the DoFs are in p4est's order now, and a resumed run has no history
    predictor.forget();
    return saved.step;
  }



  template <int dim>
  void
  TimeLoop<dim>::run_steps(const unsigned int first_step,
                           BlockVector       &state,
                           const BlockVector *first_start_value)
  {
    const unsigned int checkpoints = settings.checkpoint_interval;
    for (unsigned int step = first_step; step <= final_step; ++step)
      {
        old_state              = state;
        old_energies           = energies_of(state);
        const double tried_tau = first_step_size(step);
        Attempt      attempt{tried_tau, false};
        if (step == first_step && first_start_value != nullptr)
          state = *first_start_value;
        else
          attempt = predict_start_value(step, state, tried_tau);
        const StepResult result =
          advance_on_resolving_mesh(step, state, attempt);
        changed_on_resume = false;
        const double tau  = result.tau;
        if (extrapolates())
          predictor.record(old_state, state, tau, scheme.start_extrapolation());
        if (settings.regrow_step_size)
          step_size_limit = tau < tried_tau ? tau : 2 * tau;
        client.step_accepted(step,
                             old_state,
                             old_energies,
                             state,
                             result.energies,
                             result.report,
                             tau,
                             tried_tau);
        state_tau = tau;
        time += tau;
        last_step = step;
        // tau = tried_tau / 2^halvings exactly
        const auto halvings =
          static_cast<unsigned int>(std::lround(std::log2(tried_tau / tau)));
        record(step, state, result.energies, result.report, tau, halvings);
        // asked after every step, the last one too: the client may keep
        // a history that a checkpoint of this step holds
        const bool client_finished =
          client.finished(step, state, result.energies);
        const bool finished = step == final_step || client_finished;
        // a checkpoint holds the start of the next step: after the last
        // step too, the mesh is adapted for it
        const bool checkpoint = checkpoints > 0 && step % checkpoints == 0;
        if (settings.adaptive && step % settings.refinement_interval == 0 &&
            (!finished || checkpoint))
          remesh(state);
        if (checkpoint)
          write_checkpoint(step, state, finished);
        if (finished)
          break;
        stop_if_requested(step, state, checkpoint);
      }
  }



  template <int dim>
  void
  TimeLoop<dim>::stop_if_requested(const unsigned int step,
                                   BlockVector       &state,
                                   const bool         checkpoint_written)
  {
    const std::string signal =
      stop_requested(discretization.get_mpi_communicator());
    if (signal.empty())
      return;
    std::string checkpoint =
      "no checkpoint was written (<Checkpoint / Interval> = 0).";
    if (settings.checkpoint_interval > 0)
      {
        // the state is that of the start of the next step (re-meshed)
        if (!checkpoint_written)
          write_checkpoint(step, state, false);
        checkpoint = "the checkpoint of this step is in <" +
                     settings.output_directory + "/checkpoint-" +
                     std::to_string(step) +
                     ">: continue with <Checkpoint / Resume> = true.";
      }
    throw StopRequest("Stopped by " + signal + " after step " +
                      std::to_string(step) +
                      ": statistics.csv and the output are complete up to "
                      "this step, and " +
                      checkpoint);
  }



  template <int dim>
  bool
  TimeLoop<dim>::extrapolates() const
  {
    return settings.extrapolated_start && scheme.iterates_from_start_value();
  }



  template <int dim>
  typename TimeLoop<dim>::Attempt
  TimeLoop<dim>::predict_start_value(const unsigned int step,
                                     BlockVector       &state,
                                     const double       tau)
  {
    if (!extrapolates())
      return {tau, false};
    BlockVector extrapolated(state);
    if (!predictor.predict(extrapolated, tau))
      return {tau, false};
    if (settings.verbose)
      pcout << "  step " << step
            << ": a start extrapolated from the last two steps" << std::endl;
    const bool taken =
      scheme.take_extrapolated_start(old_state, state, extrapolated, tau);
    if (taken)
      state.swap(extrapolated);
    if (settings.verbose)
      pcout << "  step " << step << " starts from "
            << (taken ? "the extrapolation" : "the last result") << std::endl;
    return {tau, taken};
  }



  template <int dim>
  double
  TimeLoop<dim>::first_step_size(const unsigned int step) const
  {
    const double scheduled =
      client.next_step_size(settings.model.step_size(step - step_offset));
    return step_size_limit > 0 ? std::min(scheduled, step_size_limit) :
                                 scheduled;
  }



  template <int dim>
  void
  TimeLoop<dim>::write_checkpoint(const unsigned int step,
                                  BlockVector       &state,
                                  const bool         finished)
  {
    TimerOutput::Scope t(timer, "checkpoint: write");
    Checkpoint::State  saved;
    saved.step            = step;
    saved.time            = time;
    saved.state_tau       = state_tau;
    saved.step_size_limit = step_size_limit;
    saved.n_fields        = state.n_blocks();
    saved.pvd_records     = discretization.get_pvd_records();
    saved.step_offset     = step_offset;
    saved.finished        = finished && step != final_step;
    saved.problem_data    = client.checkpoint_data();
    // the fields a change of the mesh carries: the packing of the others
    // would be the peak of the step's memory (TimeSteppingScheme::
    // restores_after_remesh()); the reload below restores them
    BlockVector carried   = carried_part(state);
    saved.n_stored_fields = carried.n_blocks();
    try
      {
        Checkpoint::write(settings.output_directory,
                          discretization,
                          carried,
                          saved,
                          settings.checkpoint_parameters);
      }
    catch (...)
      {
        give_back(carried, state, false);
        throw;
      }
    give_back(carried, state, false);
    pcout << "  checkpoint written after step " << step << std::endl;
    // continue from what was written, as a resumed run does: the same
    // cell and DoF order, a fresh solver
    load_checkpoint(state);
  }



  template <int dim>
  typename TimeLoop<dim>::StepResult
  TimeLoop<dim>::advance_on_resolving_mesh(const unsigned int step,
                                           BlockVector       &state,
                                           const Attempt      attempt)
  {
    StepResult result = advance_with_halving(step, state, state_tau, attempt);
    for (unsigned int repetition = 1;
         settings.adaptive && client.repeats_unresolved_steps() &&
         !discretization.resolves_band(state);
         ++repetition)
      {
        if (repetition > max_step_repetitions)
          {
            pcout << "  Warning: step " << step
                  << ": the interface left the band of finest cells again "
                     "after "
                  << max_step_repetitions
                  << " repetitions on refined meshes; the step is kept"
                  << std::endl;
            break;
          }
        pcout << "  step " << step
              << ": the interface left the band of finest cells; "
                 "repeating the step on the mesh refined there"
              << std::endl;
        refine_to_band(state, result.tau);
        StepResult repeated = advance_with_halving(step,
                                                   state,
                                                   result.tau,
                                                   Attempt{result.tau, false});
        repeated.report     = combine(result.report, repeated.report);
        result              = repeated;
      }
    return result;
  }



  template <int dim>
  void
  TimeLoop<dim>::refine_to_band(BlockVector &state, const double tau)
  {
    TimerOutput::Scope t(timer, "mesh: adapt");
    BlockVector        carried_state = carried_part(state);
    BlockVector        carried_old   = carried_part(old_state);
    const bool         changed       = discretization.refine_to_band(
      with_history({&carried_state, &carried_old}));
    give_back(carried_state, state, changed);
    give_back(carried_old, old_state, changed);
    if (!changed)
      return;
    distribute_history_constraints();
    // old_state last: a scheme may keep data of the start of the step
    // (the semi-implicit scheme's F(U^k))
    restore_after_transfer(state, tau);
    restore_after_transfer(old_state, state_tau);
    // the start of the step on the mesh of the step
    old_energies = scheme.energies(old_state);
  }



  template <int dim>
  std::vector<BlockVector *>
  TimeLoop<dim>::with_history(std::vector<BlockVector *> fields)
  {
    for (BlockVector *v : predictor.history())
      fields.push_back(v);
    return fields;
  }



  template <int dim>
  BlockVector
  TimeLoop<dim>::carried_part(BlockVector &fields) const
  {
    return take_blocks(fields, carried_blocks(fields.n_blocks()));
  }



  template <int dim>
  void
  TimeLoop<dim>::give_back(BlockVector &carried,
                           BlockVector &fields,
                           const bool   changed) const
  {
    if (changed)
      discretization.reinit(fields, fields.n_blocks());
    swap_into(carried_blocks(fields.n_blocks()), carried, fields);
  }



  template <int dim>
  std::vector<unsigned int>
  TimeLoop<dim>::all_blocks(const unsigned int n_fields)
  {
    std::vector<unsigned int> blocks(n_fields);
    std::iota(blocks.begin(), blocks.end(), 0u);
    return blocks;
  }



  template <int dim>
  std::vector<unsigned int>
  TimeLoop<dim>::carried_blocks(const unsigned int n_fields) const
  {
    // block 0, the phase field, is always carried: the mesh follows it
    std::vector<unsigned int> blocks{0};
    for (unsigned int b = 1; b < n_fields; ++b)
      if (!scheme.restores_after_remesh(b))
        blocks.push_back(b);
    return blocks;
  }



  template <int dim>
  void
  TimeLoop<dim>::distribute_history_constraints()
  {
    for (BlockVector *v : predictor.history())
      discretization.distribute_constraints(*v);
  }



  template <int dim>
  void
  TimeLoop<dim>::restore_after_transfer(BlockVector &fields, const double tau)
  {
    client.after_remesh(fields);
    discretization.distribute_constraints(fields);
    scheme.after_remesh(fields, tau);
    discretization.distribute_constraints(fields);
  }



  template <int dim>
  typename TimeLoop<dim>::StepResult
  TimeLoop<dim>::advance_with_halving(const unsigned int step,
                                      BlockVector       &state,
                                      const double       start_tau,
                                      Attempt            attempt)
  {
    TimerOutput::Scope t(timer, "time step");
    // the start of the step for a retry; a copy (8 B per DoF) only where
    // it is not old_state: the coarse start, the extrapolated start, a
    // step repeated on a refined mesh
    std::optional<BlockVector> saved;
    if (!same_values(state, old_state))
      saved.emplace(state);
    unsigned int halvings = 0;
    double      &tau      = attempt.tau;
    for (;;)
      {
        scheme.prepare_step(state, start_tau, tau);
        const StepReport report = client.advance(scheme, old_state, state, tau);
        const bool       from_extrapolation = attempt.from_extrapolation;
        attempt.from_extrapolation          = false;
        std::string failure =
          "the solver of the " + scheme.name() + " scheme did not converge";
        if (report.converged)
          {
            const Energies energies = scheme.energies(state);
            failure                 = rejection(state, energies, tau);
            if (failure.empty())
              return {report, tau, energies};
          }
        if (from_extrapolation)
          {
            // the extrapolation is for this tau: the same step from the
            // last result (old_state), then halvings from there
            saved.reset();
            state = old_state;
            pcout << "  step " << step << ": " << failure
                  << " from the extrapolated start, retrying from the last "
                     "result"
                  << std::endl;
            continue;
          }
        state = saved ? *saved : old_state;
        if (!std::isfinite(report.final_residual_norm))
          non_finite_residual_message(step, tau);
        AssertThrow(halvings < settings.max_step_halvings,
                    ExcMessage(step_failure_message(
                      failure, scheme.name(), step, halvings, tau)));
        ++halvings;
        tau *= 0.5;
        pcout << "  step " << step << ": " << failure
              << ", retrying with half the time step, tau = " << tau
              << std::endl;
      }
  }



  template <int dim>
  void
  TimeLoop<dim>::non_finite_residual_message(const unsigned int step,
                                             const double       tau) const
  {
    pcout << "  step " << step << ": the residual of the " << scheme.name()
          << " scheme became "
          << "not finite (nan or inf) at tau = " << tau
          << ": the discrete system is too badly scaled. Check <Time "
             "stepping / Inner tau> (the curvature is (U - V) / inner tau; "
             "this run has inner tau = "
          << settings.model.inner_tau
          << ", epsilon = " << settings.model.epsilon
          << ") and <Phase field / Epsilon>." << std::endl;
  }



  template <int dim>
  std::string
  TimeLoop<dim>::rejection(const BlockVector &state,
                           const Energies    &energies,
                           const double       tau) const
  {
    std::ostringstream why;
    why << std::setprecision(4);
    if (scheme.has_energy_law() && client.energy_law_applies() &&
        !changed_on_resume)
      {
        const double before = scheme.energy_law_energy(old_energies);
        const double rise   = scheme.energy_law_energy(energies) +
                            scheme.dissipation(old_state, state, tau) - before;
        if (settings.verbose)
          pcout << "  energy + dissipation - energy before the step: "
                << std::setprecision(4) << rise << std::endl;
        if (rise > scheme.energy_law_tolerance() * std::abs(before))
          {
            why << "energy + dissipation exceeds the energy before the step "
                   "by "
                << rise
                << " (thesis Cor. 3.3 holds for the minimiser of the outer "
                   "energy: the solver found another critical point)";
            return why.str();
          }
      }
    const double inside_before = old_energies.inside_measure;
    const double inside_after  = energies.inside_measure;
    const double factor        = settings.max_inside_change_factor;
    if (factor > 0 && inside_before > 0 &&
        (inside_after > factor * inside_before ||
         inside_after * factor < inside_before))
      why << "the inside measure changed from " << inside_before << " to "
          << inside_after
          << ", by more than the factor <Time stepping / Largest inside "
             "change factor> = "
          << factor << " (the solver jumped to another branch)";
    return why.str();
  }



  template <int dim>
  Energies
  TimeLoop<dim>::energies_of(const BlockVector &state) const
  {
    return state_energies ? *state_energies : scheme.energies(state);
  }



  template <int dim>
  void
  TimeLoop<dim>::remesh(BlockVector &state)
  {
    TimerOutput::Scope t(timer, "mesh: adapt");
    const bool   report_energy = settings.verbose && scheme.has_energy_law();
    const double before =
      report_energy ? scheme.energy_law_energy(energies_of(state)) : 0.;
    BlockVector carried = carried_part(state);
    const bool  changed =
      discretization.adapt_to_phase_field(with_history({&carried}), 1., true);
    give_back(carried, state, changed);
    if (!changed)
      return;
    distribute_history_constraints();
    discretization.reinit(old_state, state.n_blocks());
    restore_after_transfer(state, state_tau);
    state_energies.reset();
    if (report_energy)
      {
        state_energies       = scheme.energies(state);
        const auto precision = pcout.get_stream().precision(10);
        pcout << "  re-meshing: energy " << before << " -> "
              << scheme.energy_law_energy(*state_energies) << std::endl;
        pcout.get_stream().precision(precision);
      }
  }



  template <int dim>
  void
  TimeLoop<dim>::record(const unsigned int step,
                        const BlockVector &state,
                        const Energies    &e,
                        const StepReport  &report,
                        const double       tau,
                        const unsigned int halvings,
                        const bool         with_output)
  {
    state_energies     = e;
    const double error = client.l2_error(state, time);
    const double dofs  = double(scheme.n_fields()) * discretization.n_dofs();
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
                          report.counts_of(scheme.statistics_columns()),
                          std::vector<double>{double(halvings)},
                          energy_term_values(client.outer_energy(),
                                             discretization.get_operators(),
                                             state.block(0)),
                          extras));
    pcout << "step " << std::setw(4) << step << "  t = " << std::setw(11)
          << std::setprecision(5) << time << "  newton "
          << report.newton_iterations << " (linear " << report.linear_iterations
          << ")  W = " << std::setprecision(7) << e.willmore
          << "  A = " << e.area << "  inside = " << e.inside_measure;
    if (!std::isnan(error))
      pcout << "  L2 error = " << std::setprecision(4) << error;
    const std::vector<std::string> extra_names = client.extra_columns();
    for (unsigned int i = 0; i < extras.size(); ++i)
      pcout << "  " << extra_names[i] << " = " << std::setprecision(5)
            << extras[i];
    pcout << "  cells " << cells << "  [" << std::setprecision(3)
          << wall_timer.wall_time() << " s]" << std::endl;
    if (with_output && settings.vtu_interval > 0 &&
        (step % settings.vtu_interval == 0 || step == final_step))
      output_results(step, state);
  }



  template <int dim>
  void
  TimeLoop<dim>::output_results(const unsigned int step,
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
    discretization.write_output(settings.output_directory, step, time, fields);
  }



  template class TimeLoop<2>;
  template class TimeLoop<3>;
} // namespace PhaseField
