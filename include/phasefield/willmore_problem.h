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

#include <phasefield/lumped_operators.h>
#include <phasefield/nested_scheme.h>
#include <phasefield/newton_solver.h>
#include <phasefield/parameters.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace PhaseField
{
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
    explicit WillmoreProblem(const WillmoreParameters &parameters);

    /** Run the whole simulation. Throws on failure. */
    void
    run();

    /** The state after run() ((U, V, P) or (U, F)), e.g. for tests. */
    const dealii::TrilinosWrappers::MPI::BlockVector &
    state() const
    {
      return solution;
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
    /** Curvature field of the current state (see output_results()). */
    void
    compute_curvature(Vector &curvature) const;

    const WillmoreParameters &prm;
    MPI_Comm                  mpi_communicator;
    dealii::ConditionalOStream pcout;
    dealii::TimerOutput        computing_timer;

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    dealii::FE_Q<dim>                                 fe;
    dealii::DoFHandler<dim>                           dof_handler;
    dealii::AffineConstraints<double>                 constraints;
    LumpedOperators<dim>                              operators;
    std::unique_ptr<ReducedSystemSolver>              linear_solver;

    std::unique_ptr<dealii::Function<dim>> signed_distance;

    /** Current state and the state at the previous time step. */
    BlockVector solution;
    BlockVector old_solution;

    std::vector<std::pair<double, std::string>> pvd_records;
  };
} // namespace PhaseField

#endif
