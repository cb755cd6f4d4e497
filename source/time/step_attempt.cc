#include <cmath>
#include <deal.II/base/exceptions.h>
#include <iomanip>
#include <optional>
#include <phasefield/time/step_attempt.h>
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
  StepAttempt<dim>::StepAttempt(const TimeLoopSettings   &settings,
                                TimeSteppingScheme<dim>  &scheme,
                                TimeLoopClient<dim>      &client,
                                const ConditionalOStream &pcout,
                                TimerOutput              &timer,
                                LoopData                 &data,
                                const StepSizePolicy     &step_sizes)
    : settings(settings)
    , scheme(scheme)
    , client(client)
    , pcout(pcout)
    , timer(timer)
    , data(data)
    , step_sizes(step_sizes)
  {}



  template <int dim>
  bool
  StepAttempt<dim>::extrapolates() const
  {
    return settings.extrapolated_start && scheme.iterates_from_start_value();
  }



  template <int dim>
  typename StepAttempt<dim>::Attempt
  StepAttempt<dim>::predict_start_value(const unsigned int step,
                                        BlockVector       &state,
                                        const double       tau)
  {
    if (!extrapolates())
      return {tau, false};
    BlockVector extrapolated(state);
    if (!data.predictor.predict(extrapolated, tau))
      return {tau, false};
    if (settings.verbose)
      pcout << "  step " << step
            << ": a start extrapolated from the last two steps" << std::endl;
    const bool taken =
      scheme.take_extrapolated_start(data.old_state, state, extrapolated, tau);
    if (taken)
      state.swap(extrapolated);
    if (settings.verbose)
      pcout << "  step " << step << " starts from "
            << (taken ? "the extrapolation" : "the last result") << std::endl;
    return {tau, taken};
  }



  template <int dim>
  typename StepAttempt<dim>::Result
  StepAttempt<dim>::advance_with_halving(const unsigned int step,
                                         BlockVector       &state,
                                         const double       start_tau,
                                         Attempt            attempt)
  {
    TimerOutput::Scope t(timer, "time step");
    // the start of the step for a retry; a copy (8 B per DoF) only where
    // it is not old_state: the coarse start, the extrapolated start, a
    // step repeated on a refined mesh
    std::optional<BlockVector> saved;
    if (!same_values(state, data.old_state))
      saved.emplace(state);
    unsigned int halvings = 0;
    double      &tau      = attempt.tau;
    for (;;)
      {
        const StepReport report = client.prepared_advance(
          scheme, data.old_state, state, start_tau, tau);
        const bool from_extrapolation = attempt.from_extrapolation;
        attempt.from_extrapolation    = false;
        std::string failure =
          "the solver of the " + scheme.name() + " scheme did not converge";
        bool error_too_large = false;
        if (report.converged)
          {
            const Energies energies = scheme.energies(state);
            failure                 = rejection(state, energies, tau);
            if (failure.empty())
              {
                failure         = error_rejection(step, state, tau, halvings);
                error_too_large = !failure.empty();
              }
            if (failure.empty())
              return {report, tau, energies};
          }
        // the extrapolation is for this tau: halvings start from the last
        // result (old_state)
        if (from_extrapolation)
          saved.reset();
        // the same step from the last result, unless only its error was too
        // large (which does not depend on the start of its iteration)
        if (from_extrapolation && !error_too_large)
          {
            state = data.old_state;
            pcout << "  step " << step << ": " << failure
                  << " from the extrapolated start, retrying from the last "
                     "result"
                  << std::endl;
            continue;
          }
        state = saved ? *saved : data.old_state;
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
  StepAttempt<dim>::non_finite_residual_message(const unsigned int step,
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
  StepAttempt<dim>::rejection(const BlockVector &state,
                              const Energies    &energies,
                              const double       tau) const
  {
    std::ostringstream why;
    why << std::setprecision(4);
    if (scheme.has_energy_law() && client.energy_law_applies() &&
        !data.changed_on_resume &&
        scheme.energy_law_applies_from(data.old_state))
      {
        const double before = scheme.energy_law_energy(data.old_energies);
        const double rise   = scheme.energy_law_energy(energies) +
                            scheme.dissipation(data.old_state, state, tau) -
                            before;
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
    const double inside_before = data.old_energies.inside_measure;
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
  std::string
  StepAttempt<dim>::error_rejection(const unsigned int step,
                                    const BlockVector &state,
                                    const double       tau,
                                    const unsigned int halvings) const
  {
    const std::string why = step_sizes.rejection(data.old_state, state, tau);
    if (why.empty() || halvings < settings.max_step_halvings)
      return why;
    pcout << "  Warning: step " << step << ": " << why << " after " << halvings
          << " halvings; the step is taken (where the estimate does not "
             "fall with the step size, the state changes faster than the "
             "time step resolves: a topology change, or data far from the "
             "discrete profile)"
          << std::endl;
    return "";
  }



  template class StepAttempt<2>;
  template class StepAttempt<3>;
} // namespace PhaseField
