// Checkpoint and resume of willmore_flow (quarter circle, small adaptive
// mesh, re-meshing every step, VTU output): a run of 4 steps with
// Checkpoint / Interval = 2 is compared with
//  - a run of 2 steps (checkpoint after its last step) resumed up to 4;
//  - a run of 3 steps (checkpoint after step 2, then one more row, as from
//    a run killed after its checkpoint) resumed up to 4, which must drop
//    that row and compute step 3 again.
// In serial the statistics.csv rows (all columns but wall_seconds) and the
// final fields agree bitwise (direct solver). On 2 ranks even two
// identical runs differ by round-off, so there the columns but
// residual_norm are compared to the digits of statistics.csv. Also:
// Resume without a checkpoint is an InputError on every rank, and the
// resumed .pvd lists the outputs of both parts. The .mpirun=2 variant
// saves and loads on 2 ranks.

#include "tests.h"

#include <algorithm>
#include <deal.II/base/mpi.h>

namespace
{
  using namespace PhaseField;

  const std::string base_prm = R"(
set Dimension = 2
subsection Geometry
  set Shape = quarter circle
  set Radius = 0.4
end
subsection Mesh
  set Finest level = 6
  set Coarsest level = 3
end
subsection Time stepping
  set Tau = 0.03*h
  set Inner tau = h^2
end
subsection Output
  set VTU interval = 2
end
subsection Checkpoint
  set Interval = 2
end
)";

  using Testing::RunResult;

  /** willmore_flow for @p n_steps steps into @p directory. */
  RunResult
  run(const std::string &directory,
      const unsigned int n_steps,
      const bool         resume)
  {
    return Testing::run_with_checkpoints<WillmoreFlowParameters,
                                         WillmoreProblem<2>>(base_prm,
                                                             directory,
                                                             n_steps,
                                                             resume);
  }

  /**
   * Print whether @p resumed agrees with @p reference. In serial it must
   * agree bitwise. On 2 ranks two identical runs already differ by
   * round-off (from the parallel direct solver): residual_norm of the
   * converged step, and the GMRES count linear_iterations, which a
   * round-off difference can move by one (12 against 13 in step 4 of a
   * CI run, 2026-11-27). So there the columns but these two are compared
   * to the digits that statistics.csv keeps.
   */
  void
  compare(const std::string &name,
          const RunResult   &reference,
          const RunResult   &resumed)
  {
    constexpr double csv_digits_tolerance = 1e-8;
    Testing::log() << name << ": " << resumed.rows.size()
                   << " rows, all columns but wall_seconds, "
                      "residual_norm and linear_iterations agree to 1e-8: "
                   << (Testing::max_relative_difference(
                         reference,
                         resumed,
                         {"residual_norm", "linear_iterations"}) <=
                           csv_digits_tolerance ?
                         "yes" :
                         "NO")
                   << std::endl;
    if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      return;
    constexpr double tolerance = 1e-12;
    Testing::log() << "  all columns but wall_seconds agree to 1e-12: "
                   << (Testing::max_relative_difference(reference, resumed) <=
                           tolerance ?
                         "yes" :
                         "NO")
                   << ", final fields bitwise equal: "
                   << (reference.field_norms == resumed.field_norms ? "yes" :
                                                                      "NO")
                   << std::endl;
  }

  /** Number of <DataSet entries in @p filename. */
  unsigned int
  n_pvd_records(const std::string &filename)
  {
    std::ifstream in(filename);
    std::string   line;
    unsigned int  n = 0;
    while (std::getline(in, line))
      if (line.find("<DataSet") != std::string::npos)
        ++n;
    return n;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const RunResult reference = run("uninterrupted", 4, false);
  Testing::print_columns(reference.rows,
                         reference.header,
                         Testing::checked_columns());

  run("resumed_after_last_step", 2, false);
  compare("resumed after the last step of a run",
          reference,
          run("resumed_after_last_step", 4, true));
  Testing::log() << "solution.pvd records: "
                 << n_pvd_records("resumed_after_last_step/solution.pvd")
                 << " (uninterrupted: "
                 << n_pvd_records("uninterrupted/solution.pvd") << ")"
                 << std::endl;

  run("resumed_after_kill", 3, false);
  compare("resumed after a run killed one step after its checkpoint",
          reference,
          run("resumed_after_kill", 4, true));

  bool input_error = false;
  try
    {
      run("no_checkpoint", 4, true);
    }
  catch (const InputError &error)
    {
      input_error =
        std::string(error.what()).find("<Checkpoint / Resume>") !=
          std::string::npos &&
        std::string(error.what()).find("no_checkpoint") != std::string::npos;
    }
  Testing::log() << "Resume without a checkpoint: InputError naming the "
                    "parameter and the directory on every rank: "
                 << (dealii::Utilities::MPI::min(int(input_error),
                                                 MPI_COMM_WORLD) ?
                       "yes" :
                       "NO")
                 << std::endl;
}
