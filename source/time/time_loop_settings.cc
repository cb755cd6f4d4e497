#include <limits>
#include <phasefield/time/checkpoint.h>
#include <phasefield/time/time_loop_settings.h>
#include <string>

namespace PhaseField
{
  unsigned int
  TimeLoopSettings::n_steps() const
  {
    // half the range: a step offset (TimeLoop::continue_run()) adds to it
    constexpr unsigned int unbounded =
      std::numeric_limits<unsigned int>::max() / 2;
    return model.step_control.end_time > 0 ? unbounded :
                                             model.n_ramp_steps + model.n_steps;
  }



  TimeLoopSettings
  TimeLoopSettings::from(const WillmoreParameters &parameters,
                         const std::string        &program_name)
  {
    TimeLoopSettings s;
    s.model                    = parameters.model;
    s.max_step_halvings        = parameters.newton.max_step_halvings;
    s.max_inside_change_factor = parameters.model.max_inside_change_factor;
    s.regrow_step_size         = parameters.newton.regrow_step_size;
    s.adaptive                 = parameters.mesh.adaptive;
    s.refinement_interval      = parameters.mesh.refinement_interval;
    s.vtu_interval             = parameters.output.vtu_interval;
    s.surface_format           = parameters.output.surface_format;
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
} // namespace PhaseField
