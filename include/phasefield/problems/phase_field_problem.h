#ifndef phasefield_problems_phase_field_problem_h
#define phasefield_problems_phase_field_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <memory>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/schemes/outer_energy.h>
#include <phasefield/schemes/time_stepping_scheme.h>
#include <phasefield/time/time_loop.h>
#include <string>

namespace PhaseField
{
  /**
   * A gradient flow of a phase field from an initial shape, in the shape
   * of the deal.II tutorials: create the narrow-band mesh around the
   * shape, initialise the fields (U = tanh(d/eps), the others by the
   * scheme), run the TimeLoop. It owns the Discretization, the scheme
   * (made by create_time_stepping_scheme()) and the state; the programs'
   * problems derive from it and add what is their own through the
   * TimeLoop::Client functions (WillmoreProblem: the exact solution;
   * RestorationProblem: the fixed region and its pictures).
   */
  template <int dim>
  class PhaseFieldProblem : public TimeLoop<dim>::Client
  {
  public:
    using Vector      = dealii::TrilinosWrappers::MPI::Vector;
    using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

    /**
     * Run the whole simulation: from the initial shape, or with
     * `Checkpoint / Resume` from the newest checkpoint in the output
     * directory (TimeLoop::resume()). Throws on failure.
     */
    virtual void
    run();

    /** The state after run() ((U, V, P) or (U, F)), e.g. for tests. */
    const BlockVector &
    state() const
    {
      return solution;
    }

    /** The discretisation of state() (e.g. for pictures and tests). */
    const Discretization<dim> &
    get_discretization() const
    {
      return discretization;
    }

    /** What a program chooses beyond the parameters. */
    struct Setup
    {
      /** Name printed in the first line of the log. */
      std::string program_name;
      /** Signed distance of the initial shape. */
      std::shared_ptr<dealii::Function<dim>> signed_distance;
      /** Weights and fixed values of the outer energy. */
      OuterEnergy outer_energy;
      /** Narrow-band hysteresis (Discretization::Settings). */
      double coarsening_band_factor = 1;
    };

  protected:
    PhaseFieldProblem(const WillmoreParameters &parameters, const Setup &setup);

    /**
     * U = tanh(d/eps) at the nodes, then the other fields by the scheme.
     * Called once the mesh exists.
     */
    virtual void
    initialize_fields();

    /**
     * Make the scheme of @p parameters (Time stepping / Scheme, epsilon,
     * inner tau, Newton and linear-solver settings) with the outer energy
     * of the setup.
     */
    void
    create_scheme(const WillmoreParameters &parameters);

    /** The first lines of the log: what runs, with which solver. */
    void
    print_header() const;

    const WillmoreParameters  &prm;
    const Setup                setup;
    const MPI_Comm             mpi_communicator;
    dealii::ConditionalOStream pcout;
    dealii::TimerOutput        computing_timer;
    Discretization<dim>        discretization;
    BlockVector                solution;

    std::unique_ptr<TimeSteppingScheme<dim>> scheme;
  };
} // namespace PhaseField

#endif
