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

  const std::string base_prm = R"(
set Dimension = 2
subsection Geometry
  set Shape  = damaged circle
  set Center = 0.5, 0
  set Radius = 0.45
end
subsection Restoration
  set Eta    = 1
  set Region = 0.25, 0.25, 0.75, 0.75
  set Damage = 0.375, 0.3, 0.625, 0.6
  set Picture resolution = 64
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
  set VTU interval = 0
end
subsection Checkpoint
  set Interval = 2
end
)";

  /**
   * edge_restoration for @p n_steps steps into @p directory; the rows of
   * statistics.csv without wall_seconds, and the l2 norms of the fields.
   */
  std::pair<std::vector<std::vector<double>>, std::vector<double>>
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
    const int wall = Testing::column(r.header, "wall_seconds");
    for (auto &row : r.rows)
      row.erase(row.begin() + wall);
    r.header.erase(r.header.begin() + wall);
    if (directory == "uninterrupted")
      Testing::check_restoration_table(r.rows, r.header);
    return {r.rows, r.field_norms};
  }

  /** Bitwise equality of two rows with NaN equal to NaN. */
  bool
  equal(const std::vector<std::vector<double>> &a,
        const std::vector<std::vector<double>> &b)
  {
    if (a.size() != b.size())
      return false;
    for (unsigned int i = 0; i < a.size(); ++i)
      for (unsigned int j = 0; j < a[i].size(); ++j)
        if (a[i][j] != b[i][j] && !(std::isnan(a[i][j]) && std::isnan(b[i][j])))
          return false;
    return true;
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
                 << (equal(reference.first, resumed.first) ? "yes" : "NO")
                 << ", final fields bitwise equal: "
                 << (reference.second == resumed.second ? "yes" : "NO")
                 << std::endl;
}
