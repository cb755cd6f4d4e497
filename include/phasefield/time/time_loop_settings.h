#ifndef phasefield_time_time_loop_settings_h
#define phasefield_time_time_loop_settings_h

#include <phasefield/core/parameters.h>
#include <string>
#include <utility>
#include <vector>

namespace PhaseField
{
  /** The parameters the time loop needs (TimeLoop::Settings). */
  struct TimeLoopSettings
  {
    /** Step sizes (ramp-up, Tau) and the number of steps. */
    ModelParameters model;
    unsigned int    max_step_halvings;
    /**
     * ModelParameters::max_inside_change_factor: the largest factor by
     * which one step may change the inside measure (0: any change).
     */
    double max_inside_change_factor;
    /** NewtonParameters::regrow_step_size. */
    bool         regrow_step_size;
    bool         adaptive;
    unsigned int refinement_interval;
    unsigned int vtu_interval;
    /** OutputParameters::surface_format. */
    SurfaceFormat surface_format = SurfaceFormat::none;
    bool          verbose;
    std::string   output_directory;
    /** Write a checkpoint every this many steps (0: never). */
    unsigned int checkpoint_interval;
    /**
     * Start steps of a scheme that iterates from its start value from
     * the StartValuePredictor's extrapolation.
     */
    bool extrapolated_start;
    /**
     * The parameters a checkpoint records and a resume compares
     * (Checkpoint::Parameters: program, Dimension, levels, Epsilon,
     * scheme, Inner tau, Adaptive).
     */
    std::vector<std::pair<std::string, std::string>> checkpoint_parameters;
    /** CheckpointParameters::allowed_changes. */
    std::vector<std::string> allowed_changes;
    /**
     * Is a resume whose checkpoint is at or after the last step
     * (nothing to do) an InputError? Not for a stage of a series
     * (shape from contour's levels), which then continues with the next
     * stage.
     */
    bool refuse_empty_resume = true;
    /**
     * The largest factor by which Client::next_step_size() may exceed the
     * scheduled sizes: the time a checkpoint may have reached by its
     * step (StepSizePolicy::latest_time()).
     */
    double largest_step_factor = 1;

    /**
     * The number of steps of a run: ramp-up steps and Number of steps, or
     * without bound where the run ends at `End time`.
     */
    unsigned int
    n_steps() const;

    /**
     * The settings of the Willmore-flow parameters of the program
     * @p program_name.
     */
    static TimeLoopSettings
    from(const WillmoreParameters &parameters,
         const std::string        &program_name = "");
  };
} // namespace PhaseField

#endif
