// willmore_flow with Scheme = augmented lagrangian on the quarter circle
// (r0 = 0.4 at the origin) on a small adaptive mesh with re-meshing after
// every step (eps = 4h, tau = inner tau = h^2): every step converges
// (al_iterations > 0 and tr_iterations > 0 in statistics.csv), and the
// printed columns are those of Scheme = nested on the same run to all 6
// digits (measured with willmore_flow: W = 1.969017, 1.943212, 1.934088;
// L2 error 0.001155, 0.0008588, 0.0009133): the AL solves the same
// discrete problem to its tolerances 1e-8. (Testing::check_quarter_circle
// is not used: it allows at most 10 Newton iterations per step, and here
// newton_iterations counts trust-region iterations, 30-100 per step.)
// The .mpirun=2 variant checks 2 ranks.

#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string>                 header;
  const auto rows = Testing::run_willmore(Testing::quarter_circle_level6 + R"(
subsection Time stepping
  set Scheme = augmented lagrangian
  set Tau = h^2
  set Number of steps = 2
end
subsection Output
  set VTU interval = 0
end
)",
                                          header);
  Testing::print_columns(
    rows,
    header,
    {"step", "willmore_energy", "area_energy", "inside_measure", "l2_error"});
  bool counted = true;
  for (unsigned int i = 1; i < rows.size(); ++i)
    counted = counted &&
              rows[i][Testing::column(header, "al_iterations")] > 0 &&
              rows[i][Testing::column(header, "tr_iterations")] > 0;
  Testing::log() << "al_iterations and tr_iterations > 0 in every step: "
                 << (counted ? "yes" : "NO") << std::endl;
}
