// Checkpoint and resume of shape_from_contour across a level transition
// (2D, levels 5 and 6, the default disc target, a checkpoint after every
// step). The levels end by the automatic transition with window 2 and a
// tolerance that always holds, so each level ends after three steps:
// rows 0-3 on level 5, the level-start row 3 and steps 4-6 on level 6.
// Against that uninterrupted run:
// - "interrupted": a run of level 5 alone for 2 steps, resumed with both
//   levels. Its third step must end level 5, which it does only if the
//   energy history of the automatic transition was restored;
// - "killed": a run of level 5 alone that ends by the transition after
//   step 3, plus the rows that a run killed on level 6 after that
//   checkpoint would have written (copied from the reference), resumed
//   with both levels. It must take no further step on level 5 (the
//   checkpoint says the level ended) and drop the copied rows, among them
//   the level-start row that repeats step 3;
// - "on level 6": a run that ends after the first step of level 6 (step
//   4), resumed with both levels from its checkpoint on level 6. Its mesh
//   must be refined to level 6 at the re-meshing after step 5, which it
//   was not before the finest level of the loaded mesh was that of the
//   checkpoint (issue 52 item 3: step 6 had fewer cells than the
//   uninterrupted run's).
// The statistics.csv rows (all columns but wall_seconds: energies,
// mismatch, labeling error, iterations) must agree bitwise with the
// uninterrupted run in serial; the .mpirun=2 variant saves and loads on 2
// ranks, where all columns but residual_norm and linear_iterations
// (round-off of the parallel direct solver: in two CI runs of the same
// commit step 4 took 94 and 93 GMRES iterations) must agree to the 10
// digits of statistics.csv; energies, mismatch and Newton counts stay
// compared.
// Resuming with other Multilevel / Levels than the writer's is an
// InputError. The checkpoints hold U alone of the nested scheme's U, V, P
// (state.txt: stored_fields; V and P are solved for U after loading,
// TimeSteppingScheme::restores_after_remesh()): the agreement above holds
// with that.

#include "tests.h"

#include <deal.II/base/mpi.h>
#include <fstream>
#include <phasefield/time/checkpoint.h>

namespace
{
  using namespace PhaseField;

  const std::string base_prm = R"(
set Dimension = 2
subsection Model
  set Area weight = 0
end
subsection Output
  set VTU interval = 0
end
subsection Checkpoint
  set Interval = 1
end
subsection Multilevel
  set Transition           = automatic
  set Transition window    = 2
  set Transition tolerance = 1e9
end
)";

  /** The parameters of a run on @p levels with @p steps per level. */
  std::string
  parameters(const std::string &levels,
             const std::string &steps,
             const bool         resume)
  {
    return base_prm + "subsection Multilevel\n set Levels = " + levels +
           "\n set Steps per level = " + steps +
           "\nend\nsubsection Checkpoint\n set Resume = " +
           (resume ? "true" : "false") + "\nend\n";
  }

  /** The full schedule: levels 5 and 6, at most 5 steps each. */
  std::string
  full(const bool resume)
  {
    return parameters("5, 6", "5, 5", resume);
  }

  /** statistics.csv of @p directory after a run on @p prm_text. */
  Testing::RunResult
  run(const std::string &prm_text, const std::string &directory)
  {
    Testing::RunResult result;
    result.rows = Testing::run_contour(prm_text, result.header, directory);
    return result;
  }

  /**
   * Whether @p resumed agrees with @p reference in all columns but
   * wall_seconds: bitwise in serial (direct solver); on 2 ranks, where two
   * identical runs already differ in residual_norm and GMRES counts (the
   * parallel direct solver), the other columns to the 10 digits of
   * statistics.csv.
   */
  std::string
  agrees(const Testing::RunResult &reference, const Testing::RunResult &resumed)
  {
    constexpr double csv_digits_tolerance = 1e-8;
    const bool       serial =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1;
    const double difference =
      serial ? Testing::max_relative_difference(reference, resumed) :
               Testing::max_relative_difference(
                 reference, resumed, {"residual_norm", "linear_iterations"});
    return difference <= (serial ? 0. : csv_digits_tolerance) ? "yes" : "NO";
  }

  /**
   * Append the lines of @p from's statistics.csv after its first
   * @p n_kept rows to @p to's, as a run killed later would have written.
   */
  void
  append_later_rows(const std::string &from,
                    const std::string &to,
                    const unsigned int n_kept)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ifstream in(from + "/statistics.csv");
        std::ofstream out(to + "/statistics.csv", std::ios::app);
        std::string   line;
        for (unsigned int i = 0; std::getline(in, line); ++i)
          if (i > n_kept) // line 0 is the header
            out << line << '\n';
      }
    MPI_Barrier(MPI_COMM_WORLD);
  }



  /**
   * "<stored> of <all>" fields of the newest checkpoint in @p directory,
   * read as a resumed run reads it. Collective.
   */
  std::string
  stored_fields(const std::string &directory)
  {
    const Checkpoint::State state =
      Checkpoint::read_state(Checkpoint::find_last(directory, MPI_COMM_WORLD),
                             MPI_COMM_WORLD);
    return std::to_string(state.n_stored_fields) + " of " +
           std::to_string(state.n_fields);
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ostream                            &log = Testing::log();

  const Testing::RunResult reference = run(full(false), "uninterrupted");
  log << "uninterrupted: steps";
  for (const auto &row : reference.rows)
    log << ' ' << row[Testing::column(reference.header, "step")];
  log << " (0-3 on level 5, the level-start row 3 and 4-6 on level 6)"
      << std::endl;
  log << "fields in its last checkpoint: " << stored_fields("uninterrupted")
      << std::endl;

  run(parameters("5", "2", false), "interrupted");
  const Testing::RunResult interrupted = run(full(true), "interrupted");
  log << "resumed after step 2 of level 5: statistics.csv agrees: "
      << agrees(reference, interrupted) << std::endl;

  run(parameters("5", "5", false), "killed");
  append_later_rows("uninterrupted", "killed", 4);
  const Testing::RunResult killed = run(full(true), "killed");
  log << "resumed after the end of level 5 (later rows dropped): "
         "statistics.csv agrees: "
      << agrees(reference, killed) << std::endl;

  run(parameters("5, 6", "5, 1", false), "level_6");
  const Testing::RunResult on_level_6 = run(full(true), "level_6");
  log << "resumed after the first step of level 6: statistics.csv agrees: "
      << agrees(reference, on_level_6) << std::endl;

  try
    {
      run(parameters("5, 7", "5, 5", true), "killed");
      log << "resume with other levels: no error" << std::endl;
    }
  catch (const InputError &error)
    {
      const std::string message = error.what();
      log << "resume with other levels: InputError naming the level: "
          << (message.find("level 6") != std::string::npos ? "yes" : "NO")
          << std::endl;
    }
}
