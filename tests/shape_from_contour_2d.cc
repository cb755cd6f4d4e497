// shape_from_contour in 2D (thesis Fig. 6.5 setting on coarse levels 5
// and 6): the labeling of a disc of radius 0.25 is reconstructed from a
// disc of radius 0.13 (mu = eta = 0.05, gamma = 10, tau = 0.03h, inner
// tau = h^2, eps = 4h). Checked against what the method must do, not
// against printed digits:
// - the mismatch j falls by a factor 10 within two steps (a do-nothing
//   step, a half-speed step or a mismatch gradient of the wrong sign do
//   not) and by 50 by the end of level 5;
// - the shape grows to the target's width: the inside measure rises from
//   the initial disc's pi 0.13^2 = 0.053 to more than 0.9 times the
//   target disc's pi 0.25^2 = 0.196 (the thesis's result is an ellipse
//   stretched along the view, not the disc: the labeling does not see the
//   depth);
// - the Willmore term acts: W falls after the first step (the first
//   mismatch step makes the interface rough);
// - the level transition: one row of the transferred state with level 6,
//   then the steps of level 6, whose mismatch ends below its start;
// - labeling.csv has one row per pixel centre of level 6, and
//   labeling_level_6.vtu a line cell between each two of them.

#include "tests.h"

#include <fstream>
#include <iterator>
#include <string>

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
subsection Multilevel
  set Levels          = 5, 6
  set Steps per level = 8, 2
end
)",
                                header);
  const auto get = [&](const unsigned int row, const std::string &name) {
    return rows[row][column(header, name)];
  };
  const double j0 = get(0, "mismatch_energy");
  log() << "rows: " << rows.size() << " (1 + 8 + 1 + 2)" << std::endl;
  log() << "j(step 2) < j(0) / 10: " << (get(2, "mismatch_energy") < j0 / 10)
        << std::endl;
  log() << "j(end of level 5) < j(0) / 50: "
        << (get(8, "mismatch_energy") < j0 / 50) << std::endl;
  log() << "inside measure: initial > 0.05, end of level 5 > 0.9 * 0.196: "
        << (get(0, "inside_measure") > 0.05 &&
            get(8, "inside_measure") > 0.9 * 0.196)
        << std::endl;
  log() << "W(end of level 5) < W(step 1): "
        << (get(8, "willmore_energy") < get(1, "willmore_energy")) << std::endl;
  log() << "transition row: step " << get(9, "step") << ", level "
        << get(9, "level") << "; level 6 mismatch falls: "
        << (get(11, "mismatch_energy") < get(9, "mismatch_energy"))
        << std::endl;
  std::ifstream csv("results/labeling.csv");
  std::string   line;
  unsigned int  n_lines = 0;
  std::getline(csv, line);
  log() << "labeling.csv header: " << line << std::endl;
  while (std::getline(csv, line))
    ++n_lines;
  log() << "labeling.csv rows: " << n_lines << std::endl;
  // the VTU of the labelings: a line through the 64 pixel centres
  std::ifstream     vtu("results/labeling_level_6.vtu");
  const std::string text((std::istreambuf_iterator<char>(vtu)),
                         std::istreambuf_iterator<char>());
  log() << "labeling_level_6.vtu has 63 cells and both labelings: "
        << (text.find("NumberOfCells=\"63\"") != std::string::npos &&
            text.find("Name=\"alpha_target\"") != std::string::npos &&
            text.find("Name=\"alpha\"") != std::string::npos)
        << std::endl;
}
