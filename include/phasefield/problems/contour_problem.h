#ifndef phasefield_problems_contour_problem_h
#define phasefield_problems_contour_problem_h

#include <deal.II/base/function.h>
#include <memory>
#include <optional>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/geometry/huffman_labeling.h>
#include <phasefield/geometry/images.h>
#include <phasefield/problems/contour_parameters.h>
#include <phasefield/problems/mismatch_term.h>
#include <phasefield/problems/phase_field_problem.h>
#include <string>
#include <utility>
#include <vector>

namespace PhaseField
{
  /**
   * Shape from apparent contour (thesis chapter 6): find a shape whose
   * Huffman labeling along the last axis is the given alpha*, minimising
   * the regularisation energy of (6.3),
   *
   *   eta a_eps[u] + mu (eps/2) ||(v-u)/ttau||^2 + gamma ||alpha* -
   * alpha[u]||^2,
   *
   * by the operator splitting of Algorithm 6.1, one step of size tau:
   *
   *  1. a nested step (thesis chapter 3) of the regularisation (weights mu,
   *     eta) with tau/2: (U, V, P)^{k+1/3};
   *  2. an explicit gradient step of the mismatch with tau and the lumped
   *     mass: eps M (U^{k+2/3} - U^{k+1/3}) = -tau G(U^{k+1/3}), with G the
   *     exact derivative of the discrete mismatch j (HuffmanLabeling);
   *     V, P unchanged;
   *  3. a nested step with tau/2 from U^{k+2/3}: (U, V, P)^{k+1}.
   *
   * The discrete j is gamma times the Gauss quadrature on the pixel grid
   * of (alpha* - alpha[U])^2, so the thesis's printed step, which applies
   * gamma twice and drops the sign of the variation, is replaced by the
   * derivative of the discrete functional.
   *
   * Multilevel (thesis 6.4): the levels of `Multilevel / Levels` coarse to
   * fine, each with its own epsilon, tau, inner tau (the expressions in h
   * at its h), pixel grid and target labeling. At a transition U, V, P are
   * transferred to the band refined to the new level and V, P are solved
   * again for U by Algorithm 3.1 (they are the inner minimiser and its
   * multiplier for the coarse level's epsilon and inner tau, not the new
   * ones). The move to the next level is fixed or automatic
   * (MultilevelParameters).
   *
   * Output, beyond willmore_flow's: the statistics columns level,
   * mismatch_energy (j with gamma), labeling_error (Int |alpha* -
   * alpha[U]| dx'), total_energy ((6.3), thesis units); labeling.csv and
   * labeling_level_<L>.csv, and a picture per level (contour_output.h).
   */
  template <int dim>
  class ContourProblem : public PhaseFieldProblem<dim>
  {
  public:
    /** @p parameters must outlive the problem. */
    explicit ContourProblem(const ContourParameters &parameters);

    /** One step of Algorithm 6.1 (nested tau/2, mismatch tau, nested tau/2). */
    StepReport
    advance(TimeSteppingScheme<dim> &scheme,
            const BlockVector       &old_state,
            BlockVector             &state,
            const double             tau) override;

    /**
     * The nested sub-steps of the split step have tau/2 (the time loop
     * prepares the multipliers for them); the monolithic step is one
     * step of @p tau.
     */
    double
    sub_step_size(const double tau) const override
    {
      return parameters.time_stepping.coupling == ContourCoupling::monolithic ?
               tau :
               0.5 * tau;
    }

    /**
     * The split step has no energy law of the nested scheme; the
     * monolithic step has that of its whole energy, mismatch included
     * (the merit function of its acceptance).
     */
    bool
    energy_law_applies() const override
    {
      return parameters.time_stepping.coupling == ContourCoupling::monolithic;
    }

    /**
     * `Time stepping / Step size control`: @p scheduled (the level's Tau,
     * or a ramp-up size) times the factor of step_accepted(); otherwise
     * @p scheduled.
     */
    double
    next_step_size(const double scheduled) const override;

    /**
     * The step-size rule: after a step that was halved, the next one tries
     * the size it took; after a step taken at the size it tried with at
     * most `Easy Newton iterations` Newton iterations whose merit
     * decrease is as a convex step energy predicts, E^k - E^{k+1} >=
     * 2 D (E = mu W + eta A + (3/4) j in geometric units, D the
     * dissipation eps ||U - U^k||_M^2 / (2 tau) in the same units; the
     * minimiser of a convex step energy satisfies it), twice that size, at
     * most `Largest tau factor` times Tau. Otherwise the same size.
     */
    void
    step_accepted(const unsigned int step,
                  const BlockVector &old_state,
                  const Energies    &old_energies,
                  const BlockVector &state,
                  const Energies    &energies,
                  const StepReport  &report,
                  const double       tau,
                  const double       tried_tau) override;

    /**
     * No: in the first steps of a level the mismatch sub-step moves the
     * interface by more than the band margin in every step
     * (shape_from_contour_2d: steps 2-6, step 2 still unresolved after 3
     * repetitions), and the figures of doc/shape_from_contour.md were
     * measured without repetitions.
     */
    bool
    repeats_unresolved_steps() const override
    {
      return false;
    }

    /**
     * The merit function (merit()): `Time stepping / Stationary tolerance`
     * ends a level when it no longer changes.
     */
    double
    stationarity_energy(const TimeSteppingScheme<dim> &scheme,
                        const BlockVector             &state,
                        const Energies                &energies) const override
    {
      (void)scheme;
      return merit(state, energies);
    }

    /** The automatic level transition. */
    bool
    finished(const unsigned int step,
             const BlockVector &state,
             const Energies    &energies) override;

    /**
     * The multilevel position for a checkpoint: the index of the level in
     * `Multilevel / Levels`, the level, and the total energies of the
     * level's steps so far (the automatic transition looks back on them).
     */
    std::vector<double>
    checkpoint_data() const override;

    /**
     * The parameters that give the state its meaning, beyond
     * willmore_flow's: the weights (`Model / Willmore weight`, `Area
     * weight`, `Mismatch weight`), the levels up to the current one
     * (`Multilevel / Levels`: later levels may be added or removed on
     * resume) and the target (`Target / Shape` with its numbers, or
     * `Image file` and `Maximum label`).
     */
    Checkpoint::Parameters
    own_checkpoint_parameters() const override;

    /** The energy history of the level from checkpoint_data(). */
    void
    after_load(BlockVector               &state,
               const std::vector<double> &problem_data) override;

    /** level, mismatch_energy, labeling_error, total_energy. */
    std::vector<std::string>
    extra_columns() const override;

    std::vector<double>
    extra_values(const BlockVector &state,
                 const Energies    &energies) const override;

    /**
     * The mismatch of U in @p state on the current pixel grid (the
     * level's MismatchTerm).
     */
    typename MismatchTerm<dim>::Evaluation
    mismatch(const BlockVector &state) const;

  protected:
    /**
     * The setup's outer energy, with the level's mismatch j as its data
     * term for the monolithic coupling (the scheme of every level refers
     * to level_mismatch, which forwards to the current level's term).
     */
    OuterEnergy
    scheme_outer_energy() const override;

    /**
     * The first level of `Multilevel / Levels`, or with `Checkpoint /
     * Resume` the level of the checkpoint (resumed_level_index()).
     */
    void
    set_first_level() override;

    /** The base's header and the levels and weights. */
    void
    print_header() const override;

    /**
     * The levels from the first one on: one scheme and one TimeLoop per
     * level (the first one resumed with `Checkpoint / Resume`), the
     * transition between them (move_to_level()) and the labelings at the
     * end of each.
     */
    void
    run_time_loops() override;

  private:
    /**
     * The sub-steps of Algorithm 6.1, in their order, and the one step of
     * the monolithic coupling.
     */
    enum class SubStep
    {
      first_nested_step,
      mismatch_step,
      second_nested_step,
      monolithic_step
    };

    /**
     * The mismatch of the current level as an EnergyTerm of fixed address
     * (OuterEnergy::data_term of the schemes): forwards to
     * ContourProblem::mismatch_term, which every level replaces.
     */
    class LevelMismatch : public EnergyTerm
    {
    public:
      explicit LevelMismatch(const std::unique_ptr<MismatchTerm<dim>> &term)
        : term(term)
      {}
      std::string
      name() const override
      {
        return term->name();
      }
      bool
      gauss_newton() const override
      {
        return true;
      }
      double
      value(const Vector &u) const override
      {
        return term->value(u);
      }
      void
      add_gradient(const Vector &u,
                   const double  factor,
                   Vector       &g) const override
      {
        term->add_gradient(u, factor, g);
      }
      void
      add_hessian_vmult(const Vector &u,
                        const Vector &d,
                        const double  factor,
                        Vector       &y) const override
      {
        term->add_hessian_vmult(u, d, factor, y);
      }
      std::unique_ptr<EnergyTerm>
      step_model(const Vector &u0) const override
      {
        // none before the first level's term exists (Algorithm 3.1 of the
        // initial state, which does not evaluate the term)
        return term ? term->step_model(u0) : nullptr;
      }

    private:
      const std::unique_ptr<MismatchTerm<dim>> &term;
    };

    /**
     * Growth factor of the step size after an easy step (step_accepted()):
     * the inverse of the time loop's halving, so that a grown step that
     * fails is retried at the size that worked.
     */
    static constexpr double step_growth = 2;

    /**
     * The smallest step size the control keeps for the next steps, as a
     * multiple of Tau: 2^-6, six halvings (the time loop halves one step
     * at most `Newton / Maximum step halvings` times, 4 by default), so
     * that a few failed steps do not leave the level at a size that it
     * needs many easy steps to regrow from.
     */
    static constexpr double min_tau_factor = 1. / 64;

    /**
     * The merit function of the step-size rule at @p state with
     * @p energies: mu W + eta A + (3/4) j, geometric units.
     */
    double
    merit(const BlockVector &state, const Energies &energies) const;

    /**
     * One level's TimeLoop from the last step @p step at @p time: run()
     * on the first level, resume() on the level of a checkpoint,
     * continue_run() otherwise. A step that fails after all halvings,
     * or in which a solver throws a deal.II exception, throws a
     * std::runtime_error (exit status 1, as other runtime failures) whose
     * message names the step, the sub-step of Algorithm 6.1 that failed
     * and the parameters to change (step_failure_message()).
     */
    void
    run_level(TimeLoop<dim>     &time_loop,
              const unsigned int index,
              const unsigned int step,
              const double       time);

    /**
     * The message of step @p step that failed: the sub-step of its last
     * attempt that did not finish, the parameters that decide whether it
     * converges, and @p reason (TimeLoop's message or the solver's).
     */
    std::string
    step_failure_message(const unsigned int step,
                         const std::string &reason) const;

    /** Entries of checkpoint_data() before the energy history. */
    static constexpr unsigned int n_level_entries = 2;

    /**
     * `Checkpoint / Resume`: the index in `Multilevel / Levels` of the
     * level of the newest checkpoint. Throws InputError if it was not
     * written by this program or on these levels. Collective.
     */
    unsigned int
    resumed_level_index() const;

    /**
     * Set the pixel grid and the target labeling of level number
     * @p index, and the parameters of that level.
     */
    void
    start_level(const unsigned int index);

    /**
     * The next level: refine the band, with `Multilevel / Sharpen
     * interface` sharpen U to the finer epsilon, new scheme, V and P for U.
     */
    void
    move_to_level(const unsigned int index);

    /** Step 2 of Algorithm 6.1 on U in @p state. */
    void
    mismatch_step(BlockVector &state, const double tau) const;

    /** Total energy (6.3) of a state with @p energies and mismatch @p j. */
    double
    total_energy(const Energies &energies, const double j) const;

    /** The target labeling on @p target_grid. */
    std::vector<double>
    target_on(const HuffmanLabeling::LabelingGrid<dim> &target_grid) const;

    /**
     * labeling_level_<L>.csv (and labeling.csv) and the pictures
     * contour_level_<L>.png and, in 3D, body_level_<L>.png.
     */
    void
    write_level_results(const bool last_level);

    /** U ghosted (for the column integrals). */
    Vector
    ghosted_u(const BlockVector &state) const;

    const ContourParameters &parameters;
    /** The index in `Multilevel / Levels` of the level the run starts on. */
    unsigned int first_level_index = 0;
    /** The index in `Multilevel / Levels` of the current level. */
    unsigned int level_index = 0;
    /**
     * The mismatch j of the current level (its pixel grid and target
     * labeling), whose gradient the explicit step of Algorithm 6.1 takes.
     */
    std::unique_ptr<MismatchTerm<dim>> mismatch_term;
    /** mismatch_term as the data term of the monolithic schemes. */
    const LevelMismatch level_mismatch{mismatch_term};
    /**
     * `Step size control`: the size the next step tries, as a multiple of
     * the level's Tau (1 at the start of every level).
     */
    double tau_factor = 1;
    /** The scheduled size of the step next_step_size() was last asked for. */
    mutable double last_scheduled = 0;
    /** Target = image: the image. */
    Images::GrayImage target_image;
    /**
     * The automatic transition's criterion (total energy or labeling
     * error) after every step of the current level.
     */
    std::vector<double> criterion_history;
    /**
     * The sub-step of Algorithm 6.1 in which the last attempt of advance()
     * stopped (it did not converge, or a solver threw) and the step size
     * of that attempt; empty after an attempt that converged.
     */
    std::optional<std::pair<SubStep, double>> unfinished_sub_step;
  };
} // namespace PhaseField

#endif
