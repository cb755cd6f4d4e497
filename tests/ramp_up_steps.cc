// Time stepping / Ramp-up steps = 3 with Number of steps = 2: the steps
// have the sizes Tau/8, Tau/4, Tau/2, Tau, Tau (statistics.csv column
// `tau`), the time is their sum, and the Willmore flow of the quarter
// circle stays on the exact law through the ramp.

#include "tests.h"


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string>                 header;
  const auto rows  = Testing::run_willmore(Testing::quarter_circle_level6 + R"(
subsection Time stepping
  set Tau = 0.03*h
  set Inner tau = h^2
  set Number of steps = 2
  set Ramp-up steps = 3
end
subsection Output
  set VTU interval = 0
end
)",
                                          header);
  const double tau = 0.03 / 64;
  const double factor[] = {1. / 8, 1. / 4, 1. / 2, 1., 1.};
  bool         sizes_ok = rows.size() == 6;
  double       time     = 0;
  for (unsigned int i = 1; sizes_ok && i < rows.size(); ++i)
    {
      time += factor[i - 1] * tau;
      const double step_size = rows[i][Testing::column(header, "tau")];
      Testing::log() << "step " << i << ": tau / Tau = " << step_size / tau
                     << std::endl;
      sizes_ok =
        sizes_ok && std::abs(step_size / (factor[i - 1] * tau) - 1) < 1e-12;
      sizes_ok =
        sizes_ok &&
        std::abs(rows[i][Testing::column(header, "time")] / time - 1) < 1e-9;
    }
  Testing::log() << "step sizes Tau/8, Tau/4, Tau/2, Tau, Tau and their sum "
                    "as time: "
                 << (sizes_ok ? "yes" : "NO") << std::endl;
  Testing::check_quarter_circle(rows, header, 0.4, 0.02, 0.10);
}
