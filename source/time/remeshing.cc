#include <numeric>
#include <phasefield/core/block_vector_tools.h>
#include <phasefield/time/remeshing.h>

namespace PhaseField
{
  using namespace dealii;



  template <int dim>
  Remeshing<dim>::Remeshing(const TimeLoopSettings   &settings,
                            Discretization<dim>      &discretization,
                            TimeSteppingScheme<dim>  &scheme,
                            TimeLoopClient<dim>      &client,
                            const ConditionalOStream &pcout,
                            TimerOutput              &timer,
                            LoopData                 &data,
                            StepSizePolicy           &step_sizes,
                            StepAttempt<dim>         &step_attempt)
    : settings(settings)
    , discretization(discretization)
    , scheme(scheme)
    , client(client)
    , pcout(pcout)
    , timer(timer)
    , data(data)
    , step_sizes(step_sizes)
    , step_attempt(step_attempt)
  {
    scheme_before_remesh = discretization.get_triangulation()
                             .signals.pre_distributed_refinement.connect(
                               [this]() { this->scheme.before_remesh(); });
  }



  template <int dim>
  void
  Remeshing<dim>::remesh(BlockVector &state)
  {
    TimerOutput::Scope t(timer, "mesh: adapt");
    const bool   report_energy = settings.verbose && scheme.has_energy_law();
    const double before =
      report_energy ?
        scheme.energy_law_energy(data.energies_of(scheme, state)) :
        0.;
    BlockVector carried = carried_part(state);
    const bool  changed =
      discretization.adapt_to_phase_field(with_history({&carried}), 1., true);
    give_back(carried, state, changed);
    if (!changed)
      return;
    distribute_history_constraints();
    discretization.reinit(data.old_state, state.n_blocks());
    restore_after_transfer(state, step_sizes.state_tau());
    data.state_energies.reset();
    if (report_energy)
      {
        data.state_energies  = scheme.energies(state);
        const auto precision = pcout.get_stream().precision(10);
        pcout << "  re-meshing: energy " << before << " -> "
              << scheme.energy_law_energy(*data.state_energies) << std::endl;
        pcout.get_stream().precision(precision);
      }
  }



  template <int dim>
  typename StepAttempt<dim>::Result
  Remeshing<dim>::advance_on_resolving_mesh(
    const unsigned int                       step,
    BlockVector                             &state,
    const typename StepAttempt<dim>::Attempt attempt)
  {
    typename StepAttempt<dim>::Result result =
      step_attempt.advance_with_halving(step,
                                        state,
                                        step_sizes.state_tau(),
                                        attempt);
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
        typename StepAttempt<dim>::Result repeated =
          step_attempt.advance_with_halving(
            step,
            state,
            result.tau,
            typename StepAttempt<dim>::Attempt{result.tau, false});
        repeated.report = combine(result.report, repeated.report);
        result          = repeated;
      }
    return result;
  }



  template <int dim>
  void
  Remeshing<dim>::refine_to_band(BlockVector &state, const double tau)
  {
    TimerOutput::Scope t(timer, "mesh: adapt");
    BlockVector        carried_state = carried_part(state);
    BlockVector        carried_old   = carried_part(data.old_state);
    const bool         changed       = discretization.refine_to_band(
      with_history({&carried_state, &carried_old}));
    give_back(carried_state, state, changed);
    give_back(carried_old, data.old_state, changed);
    if (!changed)
      return;
    distribute_history_constraints();
    // old_state last: a scheme may keep data of the start of the step
    // (the semi-implicit scheme's F(U^k))
    restore_after_transfer(state, tau);
    restore_after_transfer(data.old_state, step_sizes.state_tau());
    // the start of the step on the mesh of the step
    data.old_energies = scheme.energies(data.old_state);
  }



  template <int dim>
  std::vector<BlockVector *>
  Remeshing<dim>::with_history(std::vector<BlockVector *> fields)
  {
    for (BlockVector *v : histories())
      fields.push_back(v);
    return fields;
  }



  template <int dim>
  std::vector<BlockVector *>
  Remeshing<dim>::histories()
  {
    std::vector<BlockVector *> vectors = data.predictor.history();
    for (BlockVector *v : step_sizes.history())
      vectors.push_back(v);
    return vectors;
  }



  template <int dim>
  BlockVector
  Remeshing<dim>::carried_part(BlockVector &fields) const
  {
    return take_blocks(fields, carried_blocks(fields.n_blocks()));
  }



  template <int dim>
  void
  Remeshing<dim>::give_back(BlockVector &carried,
                            BlockVector &fields,
                            const bool   changed) const
  {
    if (changed)
      discretization.reinit(fields, fields.n_blocks());
    swap_into(carried_blocks(fields.n_blocks()), carried, fields);
  }



  template <int dim>
  std::vector<unsigned int>
  Remeshing<dim>::all_blocks(const unsigned int n_fields)
  {
    std::vector<unsigned int> blocks(n_fields);
    std::iota(blocks.begin(), blocks.end(), 0u);
    return blocks;
  }



  template <int dim>
  std::vector<unsigned int>
  Remeshing<dim>::carried_blocks(const unsigned int n_fields) const
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
  Remeshing<dim>::distribute_history_constraints()
  {
    for (BlockVector *v : histories())
      discretization.distribute_constraints(*v);
  }



  template <int dim>
  void
  Remeshing<dim>::restore_after_transfer(BlockVector &fields, const double tau)
  {
    client.after_remesh(fields);
    discretization.distribute_constraints(fields);
    scheme.after_remesh(fields, tau);
    discretization.distribute_constraints(fields);
  }



  template class Remeshing<2>;
  template class Remeshing<3>;
} // namespace PhaseField
