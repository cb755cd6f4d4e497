#ifndef phasefield_time_loop_data_h
#define phasefield_time_loop_data_h

#include <optional>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/time/start_value_predictor.h>

namespace PhaseField
{
  /**
   * What the units of the time loop (StepAttempt, Remeshing, StepRecorder,
   * Checkpointing, TimeLoop) share about the run: its time and steps, the
   * start of the current step and what is known of the current state.
   */
  struct LoopData
  {
    double time = 0;
    /** The step before the first step of this run (continue_run()). */
    unsigned int step_offset = 0;
    /** The last step of this run, step_offset + its number of steps. */
    unsigned int final_step = 0;
    BlockVector  old_state;
    /**
     * The energies of old_state on the mesh of the current step, which
     * StepAttempt::rejection() compares a result with.
     */
    Energies old_energies;
    /**
     * The energies of the state recorded last, while neither its mesh nor
     * its values changed since (re-meshing and loading a checkpoint reset
     * it): so the energies of a state are computed once, where it is the
     * result of one step and the start of the next.
     */
    std::optional<Energies> state_energies;
    /**
     * Whether the last checkpoint loaded was written with other values of
     * its recorded parameters (Checkpoint / Allow parameter change): the
     * energy of its state belongs to those, and the energy law is not
     * checked in the first step after it (StepAttempt::rejection()).
     */
    bool changed_on_resume = false;
    /** The history of the last steps (if StepAttempt::extrapolates()). */
    StartValuePredictor predictor;

    /** The energies of @p state, computed unless state_energies has them. */
    template <int dim>
    Energies
    energies_of(const TimeSteppingScheme<dim> &scheme,
                const BlockVector             &state) const
    {
      return state_energies ? *state_energies : scheme.energies(state);
    }
  };
} // namespace PhaseField

#endif
