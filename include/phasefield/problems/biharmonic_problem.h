#ifndef phasefield_biharmonic_problem_h
#define phasefield_biharmonic_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>
#include <functional>
#include <map>
#include <memory>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/quiet_timer_output.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/problems/biharmonic_parameters.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <string>
#include <vector>

namespace PhaseField
{
  /**
   * Exact solutions of the biharmonic heat flow d_t u + Lap^2 u = f on
   * [0,1]^dim, one per boundary condition, all of the separated form
   * u(t,x) = A(t) phi(x), so that f = A'(t) phi + A(t) Lap^2 phi:
   *
   * - dirichlet (thesis Lemma 4.5, in 3D with a third factor):
   *   A = e^{20t} - 1, phi = prod_i g(x_i), g(s) = s^4 - 2s^3 + s;
   * - neumann (thesis Lemma 7.2): A = e^{-pi^4 t}, phi = sum_i cos(pi x_i),
   *   f = 0;
   * - periodic: A = e^{20t} - 1, phi = sum_i cos(2 pi x_i), f =
   *   (20 e^{20t} + 16 pi^4 (e^{20t} - 1)) phi.
   */
  namespace BiharmonicSolutions
  {
    template <int dim>
    struct SeparatedSolution
    {
      /** A(t) and A'(t). */
      std::function<double(double)> amplitude;
      std::function<double(double)> amplitude_derivative;
      /** phi (value and gradient) and Lap^2 phi (value). */
      std::unique_ptr<dealii::Function<dim>> shape;
      std::unique_ptr<dealii::Function<dim>> shape_bilaplacian;
      /** false if f vanishes identically. */
      bool forced;

      /**
       * u as a Function (value and gradient; set_time() selects t). It
       * refers to this object, which must outlive it.
       */
      std::unique_ptr<dealii::Function<dim>>
      function() const;
    };

    /** The exact solution for the boundary conditions @p bc. */
    template <int dim>
    SeparatedSolution<dim>
    exact_solution(const BiharmonicBoundaryConditions bc);
  } // namespace BiharmonicSolutions

  /** Result of the computation on one mesh level. */
  struct BiharmonicLevelResult
  {
    unsigned int level;
    double       h;
    double       tau;
    double       inner_tau;
    unsigned int n_steps;
    double       time;
    unsigned int n_dofs;
    double       l2_error;
    /** Error in the full H1 norm (L2 norm and gradient). */
    double h1_error;
    /**
     * Residual norm sqrt(R.M^-1 R) of the three-field system after the
     * last step relative to the one before its solve (round-off: every
     * step is solved exactly).
     */
    double relative_residual;
    /**
     * Set-ups of the time-step matrix's preconditioner on this level (1):
     * LU factorisations (direct solver) or multigrid hierarchies
     * (iterative solver).
     */
    unsigned int n_factorizations;
    /**
     * Totals over the steps: outer and trust-region iterations of the
     * augmented Lagrangian scheme (0 for the nested one) and Krylov
     * iterations.
     */
    unsigned int al_iterations     = 0;
    unsigned int tr_iterations     = 0;
    unsigned int linear_iterations = 0;
    double       wall_seconds;
    /** Wall time of each section of the computation (TimerOutput). */
    std::map<std::string, double> section_seconds;
  };

  /**
   * The nested variational time discretization of the biharmonic heat
   * flow (thesis Definition 4.3; the nested scheme of NestedScheme with
   * epsilon = 1, no double well and the forcing of the exact solution in
   * the outer energy) on one uniform Q1 mesh of [0,1]^dim with refinement
   * level `level`, in the shape of the deal.II tutorials: make_grid(),
   * setup_system(), assemble_forcing(), run(), compute_errors().
   *
   * The three fields U, V, P share one scalar Q1 space and its
   * constraints: for Dirichlet conditions all three vanish on the
   * boundary (the ansatz space of Definition 4.1 is H^1_0 for U and V,
   * and P is the multiplier of the inner problem posed in the same
   * space); for periodic conditions they are periodic.
   *
   * The equations are linear, so one Newton step from (U^k, V^k, P^k)
   * solves a time step exactly, and the reduced matrix S of the nested
   * scheme does not depend on the state: the scheme factorises it (MUMPS,
   * `Linear solver / Type = direct`) or builds its multigrid preconditioner
   * (`iterative`) once per mesh; every time step then costs one
   * forward/backward substitution or one preconditioned CG solve.
   */
  template <int dim>
  class BiharmonicProblem
  {
  public:
    BiharmonicProblem(const BiharmonicParameters &parameters,
                      const unsigned int          level);

    /** Run the time stepping to the final time and measure the errors. */
    BiharmonicLevelResult
    run();

  private:
    void
    setup_system();
    void
    assemble_forcing(const double time);
    void
    compute_errors(const double time, BiharmonicLevelResult &result);

    const BiharmonicParameters               &biharmonic_parameters;
    const unsigned int                        level;
    const double                              h;
    const BiharmonicTimeParameters::StepSizes step_sizes;

    MPI_Comm                   mpi_communicator;
    dealii::ConditionalOStream pcout;
    /** Quiet when destroyed by an exception (QuietTimerOutput). */
    QuietTimerOutput computing_timer;

    Discretization<dim>                      discretization;
    std::unique_ptr<TimeSteppingScheme<dim>> scheme;

    const BiharmonicSolutions::SeparatedSolution<dim> exact;
    std::unique_ptr<dealii::Function<dim>>            exact_solution;

    /** Current state (U, V, P), the previous one, nodal forcing M I_h(f). */
    BlockVector solution;
    BlockVector old_solution;
    Vector      forcing_vector;
    /** M I_h(phi) and M I_h(Lap^2 phi): forcing_vector = A'(..) + A(..). */
    Vector forcing_shape;
    Vector forcing_bilaplacian;
  };

  /**
   * The convergence study of biharmonic_flow: run BiharmonicProblem on
   * every level of the parameters, write `convergence.csv` (columns
   * level,h,tau,inner_tau,time,l2_error,h1_error) into the output
   * directory and print a ConvergenceTable with the experimental orders
   * of convergence. Returns the results of all levels.
   */
  template <int dim>
  std::vector<BiharmonicLevelResult>
  run_biharmonic_convergence_study(const BiharmonicParameters &parameters);
} // namespace PhaseField

#endif
