// shape_from_contour with `Time stepping / Contour coupling = monolithic`
// and `Step size control = true` (the program's defaults otherwise: the
// thesis Fig. 6.5 disc of shape_from_contour_2d on levels 5 and 6). Checked
// against what the method must do, not against printed digits:
// - the energy law of the whole step with j (the merit function that
//   accepts a step): the total energy (6.3) does not rise from step to
//   step within a level (up to the 1e-4 relative tolerance of
//   NestedScheme::data_term_energy_law_tolerance), and falls by more than
//   a factor 3 in the first 4 steps (a do-nothing step does not; a
//   mismatch gradient of the wrong sign raises j and breaks the law);
// - the mismatch j falls by a factor 50 within 3 steps and monotonically
//   in the first 4 (measured 2.70 -> 0.51, 0.14, 0.029, 0.0050): a run at
//   the fixed step Tau, i.e. without the step-size control's growth (half
//   speed and less), ends step 3 at j = 0.12 > j(0) / 50;
// - the step-size control grows tau: 8 Tau in step 4 (Tau, 2, 4, 8 Tau:
//   every step converged in at most 5 Newton iterations with a decrease
//   of at least twice its dissipation), at most 16 Tau;
// - the shape grows to the target's width: the inside measure at the end
//   of level 5 exceeds 0.9 times the target disc's pi 0.25^2 = 0.196;
// - the level transition (with the sharpened profile, whose first level-6
//   step took 3 s instead of the transferred one's 14 s on the loaded
//   machine): a row of the transferred state with level 6, then 2 steps
//   of level 6 (a new data term on the finer pixel grid) whose total
//   energy falls.

#include "tests.h"

#include <cmath>

int
main(int argc, char **argv)
{
  using namespace Testing;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string>                 header;
  const auto                               rows = run_contour(R"(
set Dimension = 2
subsection Output
  set VTU interval = 0
end
subsection Time stepping
  set Contour coupling  = monolithic
  set Step size control = true
end
subsection Multilevel
  set Levels            = 5, 6
  set Steps per level   = 8, 2
  set Sharpen interface = true
end
)",
                                header);
  const auto get = [&](const unsigned int row, const std::string &name) {
    return rows[row][column(header, name)];
  };
  constexpr double tolerance = 1e-4;
  const auto       law_holds = [&](const unsigned int first,
                             const unsigned int last) {
    for (unsigned int row = first + 1; row <= last; ++row)
      if (get(row, "total_energy") >
          get(row - 1, "total_energy") * (1 + tolerance))
        return false;
    return true;
  };
  const double j0  = get(0, "mismatch_energy");
  const double tau = get(0, "tau");
  log() << "rows: " << rows.size() << " (1 + 8 + 1 + 2)" << std::endl;
  log() << "total energy does not rise within level 5: " << law_holds(0, 8)
        << ", within level 6: " << law_holds(9, 11) << std::endl;
  log() << "total energy(step 4) < total energy(0) / 3: "
        << (get(4, "total_energy") < get(0, "total_energy") / 3) << std::endl;
  log() << "j(step 3) < j(0) / 50: " << (get(3, "mismatch_energy") < j0 / 50)
        << std::endl;
  bool falls = true;
  for (unsigned int row = 1; row <= 4; ++row)
    falls =
      falls && get(row, "mismatch_energy") < get(row - 1, "mismatch_energy");
  log() << "j falls in steps 1-4: " << falls << std::endl;
  log() << "tau(step 4) / Tau = " << std::lround(get(4, "tau") / tau)
        << ", tau <= 16 Tau on level 5: ";
  bool bounded = true;
  for (unsigned int row = 1; row <= 8; ++row)
    bounded = bounded && get(row, "tau") <= 16 * tau * (1 + 1e-12);
  log() << bounded << std::endl;
  log() << "inside measure at the end of level 5 > 0.9 * 0.196: "
        << (get(8, "inside_measure") > 0.9 * 0.196) << std::endl;
  log() << "transition row: step " << get(9, "step") << ", level "
        << get(9, "level") << "; level 6 total energy falls: "
        << (get(11, "total_energy") < get(9, "total_energy")) << std::endl;
}
