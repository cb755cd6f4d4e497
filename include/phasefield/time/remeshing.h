#ifndef phasefield_time_remeshing_h
#define phasefield_time_remeshing_h

#include <boost/signals2/connection.hpp>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/time/loop_data.h>
#include <phasefield/time/step_attempt.h>
#include <phasefield/time/step_size_policy.h>
#include <phasefield/time/time_loop_client.h>
#include <phasefield/time/time_loop_settings.h>
#include <vector>

namespace PhaseField
{
  /**
   * The changes of the mesh of the time loop: narrow-band re-meshing of
   * the state, the refinement to the band of a step's result and the
   * repetition of the step there, and what a transfer carries (the fields
   * and the predictor's history) and restores.
   */
  template <int dim>
  class Remeshing
  {
  public:
    /**
     * Connects TimeSteppingScheme::before_remesh() to the triangulation's
     * pre_distributed_refinement signal: only when the mesh does change,
     * so that a step on an unchanged mesh keeps its solver.
     */
    Remeshing(const TimeLoopSettings           &settings,
              Discretization<dim>              &discretization,
              TimeSteppingScheme<dim>          &scheme,
              TimeLoopClient<dim>              &client,
              const dealii::ConditionalOStream &pcout,
              dealii::TimerOutput              &timer,
              LoopData                         &data,
              StepSizePolicy                   &step_sizes,
              StepAttempt<dim>                 &step_attempt);

    /** Adapt the mesh to the state and restore what the transfer broke. */
    void
    remesh(BlockVector &state);

    /**
     * Step @p step from old_state into @p state by @p attempt, halved on
     * failure or rejection (StepAttempt::advance_with_halving()); returns
     * the report and the step size taken. Where the interface of the
     * result left the band of finest cells (Discretization::
     * resolves_band()), the mesh is refined there and the step repeated
     * from old_state on it, with the result as the start value: a
     * minimiser computed on coarser cells is not the minimiser on a mesh
     * that resolves it, and its energy changes at the next re-meshing
     * (edge restoration at level 10: by half or more).
     */
    typename StepAttempt<dim>::Result
    advance_on_resolving_mesh(const unsigned int                       step,
                              BlockVector                             &state,
                              const typename StepAttempt<dim>::Attempt attempt);

    /**
     * The blocks of @p fields that a change of the mesh carries: all but
     * those the scheme restores after it (TimeSteppingScheme::
     * restores_after_remesh()), swapped out of @p fields into a block
     * vector of their own for the transfer; give_back() returns them.
     */
    BlockVector
    carried_part(BlockVector &fields) const;

    /**
     * Swap the blocks of @p carried back into @p fields, after moving
     * @p fields to the new mesh (zero there) if the mesh @p changed.
     */
    void
    give_back(BlockVector &carried,
              BlockVector &fields,
              const bool   changed) const;

    /** The indices of the blocks carried_part() takes from @p n_fields. */
    std::vector<unsigned int>
    carried_blocks(const unsigned int n_fields) const;

    /** The indices 0, ..., @p n_fields - 1. */
    static std::vector<unsigned int>
    all_blocks(const unsigned int n_fields);

  private:
    /**
     * Refine the mesh, never coarsen it, to the band of @p state, and
     * restore what the transfer broke in @p state (a result of step size
     * @p tau) and old_state.
     */
    void
    refine_to_band(BlockVector &state, const double tau);

    /**
     * After a transfer to a new mesh, restore what it broke in @p fields,
     * a state of step size @p tau: the client's data (fixed values), the
     * constraints, the scheme's fields (TimeLoopClient::after_remesh(),
     * TimeSteppingScheme::after_remesh()).
     */
    void
    restore_after_transfer(BlockVector &fields, const double tau);

    /**
     * @p fields and the vectors of the predictor's and the step-size
     * policy's histories: what a change of the mesh transfers.
     */
    std::vector<BlockVector *>
    with_history(std::vector<BlockVector *> fields);

    /** The vectors of the predictor's and the policy's histories. */
    std::vector<BlockVector *>
    histories();

    /** Distribute the constraints in the transferred histories. */
    void
    distribute_history_constraints();

    /**
     * Repetitions of a step on refined meshes (advance_on_resolving_mesh())
     * before the result is kept with a warning: each one refines where the
     * interface of the last result went, which the next result leaves
     * only if it moves on by the band margin.
     */
    static constexpr unsigned int max_step_repetitions = 3;

    const TimeLoopSettings           &settings;
    Discretization<dim>              &discretization;
    TimeSteppingScheme<dim>          &scheme;
    TimeLoopClient<dim>              &client;
    const dealii::ConditionalOStream &pcout;
    dealii::TimerOutput              &timer;
    LoopData                         &data;
    StepSizePolicy                   &step_sizes;
    StepAttempt<dim>                 &step_attempt;
    /** TimeSteppingScheme::before_remesh() on a change of the mesh. */
    boost::signals2::scoped_connection scheme_before_remesh;
  };
} // namespace PhaseField

#endif
