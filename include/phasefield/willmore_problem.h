#ifndef phasefield_willmore_problem_h
#define phasefield_willmore_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <memory>
#include <phasefield/lumped_operators.h>
#include <phasefield/nested_scheme.h>
#include <phasefield/newton_solver.h>
#include <phasefield/parameters.h>
#include <string>
#include <utility>
#include <vector>

namespace PhaseField
{
  /**
   * Optional generalisations of the Willmore problem, used by other
   * programs (edge restoration, thesis 5.3). The defaults give Willmore
   * flow.
   */
  template <int dim>
  struct WillmoreProblemOptions
  {
    /** Signed distance of the initial shape; nullptr: `Geometry`. */
    std::shared_ptr<dealii::Function<dim>> signed_distance;

    /** Weight eta of the area term in the outer energy (thesis (5.7)). */
    double area_weight = 0;

    /**
     * The open region in which U is free; empty: everywhere. At every
     * other node U is held at the initial data tanh(d/eps) (also on nodes
     * created by re-meshing), V and P are free everywhere.
     */
    std::function<bool(const dealii::Point<dim> &)> u_is_free;

    /**
     * Keep deal.II's mesh smoothing eliminate_unrefined_islands (refine a
     * coarse cell surrounded by finer ones). With narrow-band coarsening
     * far from the interface it can undo the coarsening of the previous
     * re-meshing, so that a stationary interface makes the mesh alternate
     * between two meshes (and the energy jump at every re-meshing); edge
     * restoration switches it off.
     */
    bool refine_unrefined_islands = true;

    /**
     * Cells are coarsened only outside the band of this many times
     * `Mesh / Band width` (hysteresis; 1: coarsen everything outside the
     * refinement band). Coarsening where 1 - |U| is not negligible changes
     * the discrete energy; edge restoration, whose energy must decrease
     * from step to step, uses a wider coarsening band.
     */
    double coarsening_band_factor = 1;

    /** Name printed in the first line of the log. */
    std::string program_name = "willmore_flow";

    /** Are the edge restoration terms present? */
    bool
    restoration() const
    {
      return area_weight != 0 || static_cast<bool>(u_is_free);
    }
  };

  /**
   * Willmore flow of a phase field on an adaptive (narrow-band) mesh of
   * [0,1]^dim, in the shape of the deal.II tutorials: setup_system(),
   * solve_time_step(), refine_mesh(), output_results(), run().
   *
   * The fields live in one scalar Q1 space and are stored as the blocks of
   * a Trilinos block vector: (U, V, P) for the nested scheme (see
   * NestedScheme for the equations and the Newton system), (U, F) for the
   * semi-implicit scheme (SemiImplicitScheme).
   */
  template <int dim>
  class WillmoreProblem
  {
  public:
    explicit WillmoreProblem(const WillmoreParameters          &parameters,
                             const WillmoreProblemOptions<dim> &options =
                               WillmoreProblemOptions<dim>());

    /** Run the whole simulation. Throws on failure. */
    void
    run();

    /** The state after run() ((U, V, P) or (U, F)), e.g. for tests. */
    const dealii::TrilinosWrappers::MPI::BlockVector &
    state() const
    {
      return solution;
    }

    /** The DoF handler of state() (e.g. for pictures and tests). */
    const dealii::DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

  private:
    using Vector      = dealii::TrilinosWrappers::MPI::Vector;
    using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

    void
    create_initial_mesh();
    void
    setup_system();
    void
    reinit_vector(BlockVector &v) const;
    void
    distribute_constraints(BlockVector &v) const;
    void
    initialize_fields();
    StepReport
    solve_time_step(const double tau);
    void
    refine_mesh();
    /**
     * Edge restoration: V and P of the current state re-solved for its U,
     * the inner minimiser and its adjoint for the step size @p tau (after
     * re-meshing, the transferred V is not the inner minimiser on the new
     * mesh, and the energy of the state would not be the one the next step
     * decreases).
     */
    void
    solve_inner_problem(const double tau);
    /**
     * Tolerance of ||R_P||_{M^-1} in the inner problem of edge restoration:
     * round-off is about 1e-15; an inexact V changes the outer energy to
     * first order and R_U by a = tau/ttau^2 times it.
     */
    static constexpr double inner_tolerance = 1e-14;
    double
    compute_l2_error(const double time) const;
    void
    output_results(const unsigned int step, const double time);
    NestedCoefficients
    coefficients(const double tau) const;
    /** Number of fields (blocks) of the selected scheme. */
    unsigned int
    n_fields() const;
    /** Energies of the current state (Willmore energy of the scheme). */
    Energies
    compute_energies() const;
    /** W + eta A of the current state (the `weighted_energy` column). */
    double
    weighted_energy() const;
    /**
     * The first term of the outer energy, eps ||U - U^k||^2_M / (2 tau),
     * scaled like the energies (factor 3/4): by thesis Cor. 3.3, on a fixed
     * mesh weighted_energy() after a step plus this is at most
     * weighted_energy() before it, if the step found the minimiser.
     */
    double
    dissipation(const double tau) const;
    /** Curvature field of the current state (see output_results()). */
    void
    compute_curvature(Vector &curvature) const;

    /**
     * Edge restoration: collect the DoFs with fixed U (outside
     * WillmoreProblemOptions::u_is_free) and their initial values.
     */
    void
    setup_fixed_u();
    /** Edge restoration: U = initial data at the fixed DoFs. */
    void
    reset_fixed_u();
    /** Edge restoration: max |U - initial data| over the fixed DoFs. */
    double
    fixed_u_deviation() const;
    /** Statistics columns of edge restoration (none for Willmore flow). */
    std::vector<std::string>
    extra_columns() const;
    std::vector<double>
    extra_values(const Energies &energies) const;

    const WillmoreParameters         &prm;
    const WillmoreProblemOptions<dim> options;
    MPI_Comm                          mpi_communicator;
    dealii::ConditionalOStream        pcout;
    dealii::TimerOutput               computing_timer;

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    dealii::FE_Q<dim>                                 fe;
    dealii::DoFHandler<dim>                           dof_handler;
    dealii::AffineConstraints<double>                 constraints;
    LumpedOperators<dim>                              operators;
    std::unique_ptr<ReducedSystemSolver>              linear_solver;

    std::shared_ptr<dealii::Function<dim>> signed_distance;

    /** Edge restoration: DoFs with fixed U (locally relevant). */
    dealii::IndexSet fixed_u_dofs;
    /** Edge restoration: the initial data U^0 on the current mesh. */
    Vector initial_u;

    /** Current state and the state at the previous time step. */
    BlockVector solution;
    BlockVector old_solution;

    std::vector<std::pair<double, std::string>> pvd_records;
  };
} // namespace PhaseField

#endif
