// Checkpoint and resume of edge_restoration (the damaged circle of
// edge_restoration_circle.cc, level 6): 4 steps with Checkpoint / Interval
// = 2 against 2 steps resumed up to 4. The resumed run must set up the
// fixed values on the loaded mesh; its statistics.csv rows (all columns
// but wall_seconds) and final fields agree bitwise in serial.

#include "tests.h"

#include <deal.II/base/mpi.h>

namespace
{
  using namespace PhaseField;

  const std::string base_prm = Testing::damaged_circle_restoration + R"(
subsection Time stepping
  set Tau = 0.03*h
  set Inner tau = h^2
end
subsection Output
  set VTU interval = 0
end
subsection Checkpoint
  set Interval = 2
end
)";

  /**
   * edge_restoration for @p n_steps steps into @p directory: statistics
   * and the l2 norms of the fields.
   */
  Testing::RunResult
  run(const std::string &directory,
      const unsigned int n_steps,
      const bool         resume)
  {
    Testing::RunResult r =
      Testing::run_with_checkpoints<EdgeRestorationParameters,
                                    RestorationProblem>(base_prm,
                                                        directory,
                                                        n_steps,
                                                        resume);
    if (directory == "uninterrupted")
      {
        std::vector<std::string>         header = r.header;
        std::vector<std::vector<double>> rows   = r.rows;
        const int wall = Testing::column(header, "wall_seconds");
        for (auto &row : rows)
          row.erase(row.begin() + wall);
        header.erase(header.begin() + wall);
        Testing::check_restoration_table(rows, header);
      }
    return r;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto reference = run("uninterrupted", 4, false);
  run("resumed", 2, false);
  const auto resumed = run("resumed", 4, true);
  Testing::log() << "resumed: statistics.csv rows (but wall_seconds) "
                    "bitwise equal: "
                 << (Testing::max_relative_difference(reference, resumed) == 0 ?
                       "yes" :
                       "NO")
                 << ", final fields bitwise equal: "
                 << (reference.field_norms == resumed.field_norms ? "yes" :
                                                                    "NO")
                 << std::endl;
}
