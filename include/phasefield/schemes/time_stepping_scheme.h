#ifndef phasefield_schemes_time_stepping_scheme_h
#define phasefield_schemes_time_stepping_scheme_h

#include <any>
#include <deal.II/base/conditional_ostream.h>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/energies.h>
#include <phasefield/schemes/outer_energy.h>
#include <phasefield/solvers/nonlinear_system.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * A time discretisation of a phase-field gradient flow, as the time loop
   * and the problems see it. The state of a scheme is a block vector of
   * fields in the scalar Q1 space of a Discretization, the phase field U
   * first: (U, V, P) for the nested scheme, (U, F) for the semi-implicit
   * one. Implementations: NestedScheme (thesis chapter 3),
   * SemiImplicitScheme (thesis section 5.2), AugmentedLagrangianScheme
   * (thesis chapter 7); the scheme registry (scheme_registry.h) names
   * them, and its create_time_stepping_scheme() is the only place that
   * chooses between them.
   */
  /**
   * How the start value of a step extrapolates the phase field U from the
   * last two steps (StartValuePredictor; every other field linearly).
   */
  enum class StartExtrapolation
  {
    /** U_n + min(theta, 1) (U_n - U_(n-1)). */
    linear,
    /**
     * In the profile variable phi = artanh(U) (the distance to the
     * interface in units of its width, for U = tanh(d/eps)):
     * U_n + tanh(phi_n + min(theta, 1) dphi) - tanh(phi_n), which moves the
     * interface as the last step did even by several widths, where the
     * linear extrapolation of two profiles is no profile; U_n stays where
     * phi did not change.
     */
    profile
  };



  template <int dim>
  class TimeSteppingScheme
  {
  public:
    virtual ~TimeSteppingScheme() = default;

    /** The value of `Time stepping / Scheme`, e.g. "nested". */
    virtual std::string
    name() const = 0;

    /** The names of the fields (blocks of the state), U first. */
    virtual std::vector<std::string>
    field_names() const = 0;

    /** Number of fields. */
    unsigned int
    n_fields() const
    {
      return field_names().size();
    }

    /** The linear solver, in words, for the log. */
    virtual std::string
    linear_solver_description() const = 0;

    /** Warnings about the parameters (empty if none), for the log. */
    virtual std::vector<std::string>
    warnings() const
    {
      return {};
    }

    /**
     * Given U in block 0 of @p state, set the other fields (the nested
     * scheme's Algorithm 3.1 for the step size @p tau; F = f(U)).
     */
    virtual void
    initialize(BlockVector &state, const double tau) = 0;

    /**
     * Before a (re)try of a step of size @p tau from a state that belongs
     * to steps of size @p state_tau: adjust the state (the nested scheme
     * scales P, which is proportional to tau).
     */
    virtual void
    prepare_step(BlockVector &state,
                 const double state_tau,
                 const double tau) const
    {
      (void)state;
      (void)state_tau;
      (void)tau;
    }

    /**
     * Does advance() iterate from the start value in @p state, so that a
     * better start saves iterations (StartValuePredictor)? Not for a
     * scheme whose step is one linear solve or that restarts its own
     * iteration.
     */
    virtual bool
    iterates_from_start_value() const
    {
      return false;
    }

    /**
     * How StartValuePredictor extrapolates U for this scheme.
     */
    virtual StartExtrapolation
    start_extrapolation() const
    {
      return StartExtrapolation::linear;
    }

    /**
     * Should the step of size @p tau from @p old_state start from
     * @p extrapolated (StartValuePredictor's extrapolation, which the
     * scheme may complete, e.g. by re-solving fields that depend on
     * others) rather than from @p last_result? Prints its reasons with
     * `Output / Verbose`. Only for a scheme that
     * iterates_from_start_value().
     */
    virtual bool
    take_extrapolated_start(const BlockVector &old_state,
                            const BlockVector &last_result,
                            BlockVector       &extrapolated,
                            const double       tau) const
    {
      (void)old_state;
      (void)last_result;
      (void)extrapolated;
      (void)tau;
      AssertThrow(false, dealii::ExcNotImplemented());
      return false;
    }

    /**
     * One time step of size @p tau from @p old_state: @p state holds the
     * start of the iteration and on return the new state (or, on failure,
     * the last iterate).
     */
    virtual StepReport
    advance(const BlockVector &old_state,
            BlockVector       &state,
            const double       tau) = 0;

    /**
     * Free what the scheme keeps for the current mesh (multigrid
     * hierarchies, factorisations, matrices): called when the mesh is about
     * to change, so that these and the new mesh's DoFs and matrices do not
     * exist at once (doc/benchmarks.md, "Choices in the code"). after_remesh()
     * follows.
     */
    virtual void
    before_remesh() = 0;

    /**
     * After re-meshing (fields transferred, constraints distributed):
     * reset_solver() and restore what the transfer does not keep (the
     * semi-implicit F = f(U); with restoration terms the nested V, P for
     * the U of the step size @p tau).
     */
    virtual void
    after_remesh(BlockVector &state, const double tau) = 0;

    /**
     * Whether after_remesh() computes field @p field of the state anew
     * from the others, so that a change of the mesh need not carry it:
     * the field then arrives as zero. Each field a transfer does not
     * carry saves its packing, the largest transient of a re-meshing
     * (doc/benchmarks.md, "Choices in the code"). Default: every field is
     * carried.
     */
    virtual bool
    restores_after_remesh(const unsigned int field) const
    {
      (void)field;
      return false;
    }

    /**
     * Forget all matrices and factorisations (everything the scheme keeps
     * between steps besides the state), as after re-meshing but without
     * touching a field. Called after loading a checkpoint (the mesh is
     * new) and, in every run, when a checkpoint is written: the direct
     * solver reuses old factorisations as GMRES preconditioners, so only
     * if both start with a fresh solver does a resumed run compute the
     * same steps as an uninterrupted one.
     */
    virtual void
    reset_solver() = 0;

    /** Energies of @p state in geometric units. */
    virtual Energies
    energies(const BlockVector &state) const = 0;

    /**
     * Preconditioner set-ups of the Newton solves so far: LU
     * factorisations (direct) or multigrid hierarchies (iterative).
     */
    virtual unsigned int
    n_factorizations() const = 0;

    /** The mean curvature field of @p state (for the output). */
    virtual void
    curvature(const BlockVector &state, Vector &curvature) const = 0;

    /**
     * The scheme's own columns of statistics.csv, written between
     * residual_norm and step_halvings; in the row of a step, the value of
     * each is the count of that name in the step's report
     * (StepReport::add_count(), 0 where the step did not count it). The
     * default, al_iterations and tr_iterations (the outer iterations of an
     * augmented Lagrangian method and its trust-region iterations), are
     * columns that statistics.csv has had for every scheme since the
     * augmented Lagrangian scheme came, so that the files of the built-in
     * schemes have the same columns. A scheme with counts of its own
     * returns these followed by its own.
     */
    virtual std::vector<std::string>
    statistics_columns() const
    {
      return {"al_iterations", "tr_iterations"};
    }

    /**
     * Does every exact step decrease energy_law_energy() by at least
     * dissipation() (thesis Cor. 3.3)? The time loop checks it then.
     */
    virtual bool
    has_energy_law() const
    {
      return false;
    }

    /**
     * mu W + eta A (weights of the outer energy) of a state with the
     * @p energies (energies() of the state).
     */
    virtual double
    energy_law_energy(const Energies &energies) const
    {
      (void)energies;
      return 0;
    }

    /**
     * The rise of energy_law_energy() + dissipation() above
     * energy_law_energy() before a step, relative to the latter, that the
     * round-off and the tolerances of the scheme's solver allow; the time
     * loop rejects a step above it. The default: the round-off of the
     * energies, whose curvature (U - V) / ttau loses about log10(1/ttau)
     * digits.
     */
    virtual double
    energy_law_tolerance() const
    {
      return 1e-10;
    }

    /**
     * Does the energy law hold for a step from @p old_state? The default:
     * yes. NestedScheme with held volume or area: not from a state that
     * does not have the held values (the first step with `Constraints /
     * Reduced volume`, `Volume value` or `Area value`), whose step moves
     * the interface onto the constraints and may raise the energy.
     * Collective.
     */
    virtual bool
    energy_law_applies_from(const BlockVector &old_state) const
    {
      (void)old_state;
      return true;
    }

    /** The dissipation of the step from @p old_state to @p state. */
    virtual double
    dissipation(const BlockVector &old_state,
                const BlockVector &state,
                const double       tau) const
    {
      (void)old_state;
      (void)state;
      (void)tau;
      return 0;
    }
  };

  /** What create_time_stepping_scheme() builds a scheme from. */
  struct SchemeSettings
  {
    /**
     * The scheme, a name of the scheme registry, and its own parameters
     * (read by own_parameters()).
     */
    SchemeChoice scheme;
    /** Epsilon (1 for the biharmonic model). */
    double epsilon   = 1;
    double inner_tau = 1;
    /** false: the biharmonic model problem (no Psi terms). */
    bool             double_well = true;
    OuterEnergy      outer_energy;
    NewtonParameters newton;
    /** Tolerance and iterations of `Linear solver`. */
    LinearSolverParameters linear_solver;
    /**
     * The solver and backend that `Linear solver / Type` resolved to
     * (resolve_solver_choice()), the same as the mesh's
     * (Discretization::Settings::solver).
     */
    SolverChoice solver;
    bool         verbose = false;

    /**
     * The scheme's own parameters, of the type @p Parameters that its
     * registry entry parsed (SchemeEntry::set_parameters()); the defaults
     * of @p Parameters if none were parsed (settings made in code).
     */
    template <typename Parameters>
    Parameters
    own_parameters() const
    {
      if (!scheme.parameters.has_value())
        return Parameters();
      const Parameters *parameters =
        std::any_cast<Parameters>(&scheme.parameters);
      AssertThrow(parameters != nullptr,
                  dealii::ExcMessage("The parameters of the scheme <" +
                                     scheme.name +
                                     "> are not of the type it reads."));
      return *parameters;
    }
  };
} // namespace PhaseField

#endif
