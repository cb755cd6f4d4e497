// No silent NaN in the VTU output: check_output_fields_finite(), which
// TimeLoop::output_results() calls before a VTU file is written, throws on
// every rank for a field with a NaN or an Inf, or an entry that the
// VTU file's 32-bit floats cannot hold (owned by the last rank only), with a
// message naming the step, the field, the number of such entries and the
// parameter to change, and accepts finite fields; thrown in a program, it ends
// run_program() with exit status 1. No input is known that makes a converged
// step non-finite (the energies are checked before, and Newton fails on a
// non-finite residual), so the check is tested directly. The .mpirun=2 variant
// puts the bad entry on rank 1.

#include "tests.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/utilities.h>
#include <limits>
#include <phasefield/core/program.h>
#include <phasefield/time/finite_fields.h>

namespace
{
  using Vector = dealii::TrilinosWrappers::MPI::Vector;
  using Fields = std::vector<std::pair<std::string, const Vector *>>;

  /** Entries of the test vectors. */
  constexpr unsigned int n_entries = 10;
  /** Step number passed to the check. */
  constexpr unsigned int step = 7;

  /** Ones, evenly distributed, the last entry (on the last rank) @p last. */
  Vector
  field(const double last)
  {
    const MPI_Comm     comm = MPI_COMM_WORLD;
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    const dealii::IndexSet owned =
      dealii::Utilities::create_evenly_distributed_partitioning(
        rank, dealii::Utilities::MPI::n_mpi_processes(comm), n_entries);
    Vector v(owned, comm);
    v = 1.;
    if (owned.is_element(n_entries - 1))
      v[n_entries - 1] = last;
    v.compress(dealii::VectorOperation::insert);
    return v;
  }

  /**
   * The message of the check for @p fields ("" if it does not throw),
   * every line break and indentation (deal.II wraps what()) one space.
   */
  std::string
  message(const Fields &fields)
  {
    try
      {
        PhaseField::check_output_fields_finite(step, fields);
      }
    catch (const dealii::ExceptionBase &exc)
      {
        std::istringstream words(exc.what());
        std::string        word, text;
        while (words >> word)
          text += word + ' ';
        return text;
      }
    return "";
  }

  /** Log whether every rank's message contains all of @p parts. */
  void
  check(const std::string              &what,
        const Fields                   &fields,
        const std::vector<std::string> &parts)
  {
    const std::string m  = message(fields);
    bool              ok = parts.empty() ? m.empty() : !m.empty();
    for (const auto &p : parts)
      ok = ok && m.find(p) != std::string::npos;
    const bool everywhere =
      dealii::Utilities::MPI::min(int(ok), MPI_COMM_WORLD) == 1;
    Testing::log() << what << ": " << (everywhere ? "yes" : "NO") << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  bool      root   = false;
  const int status = PhaseField::run_program(
    argc,
    argv,
    "finite_fields",
    [](dealii::ParameterHandler &) {},
    [&root](dealii::ParameterHandler &) {
      root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      const Vector ones = field(1.);
      const Vector nan  = field(std::numeric_limits<double>::quiet_NaN());
      const Vector inf  = field(std::numeric_limits<double>::infinity());
      check("finite fields accepted on every rank",
            {{"U", &ones}, {"curvature", &ones}},
            {});
      check("NaN in U: thrown on every rank naming step, field, count "
            "and <Time stepping / Tau>",
            {{"U", &nan}, {"curvature", &ones}},
            {"Step 7", "<U> has 1 entries", "<Time stepping / Tau>"});
      check("Inf in the curvature: thrown on every rank, also naming "
            "<Time stepping / Inner tau>",
            {{"U", &ones}, {"curvature", &inf}},
            {"<curvature> has 1 entries", "<Time stepping / Inner tau>"});
      // finite as a double, Inf as the VTU file's 32-bit float
      const Vector beyond_float  = field(1e39);
      const Vector largest_float = field(std::numeric_limits<float>::max());
      check("1e39 in P (Inf as a 32-bit float): thrown on every rank",
            {{"U", &ones}, {"P", &beyond_float}},
            {"Step 7", "<P> has 1 entries", "32-bit floats"});
      check("the largest 32-bit float accepted",
            {{"U", &ones}, {"P", &largest_float}},
            {});
      Testing::log().flush();
      // not caught here: run_program() turns it into the exit status
      PhaseField::check_output_fields_finite(step, {{"U", &nan}});
    });
  if (root)
    std::ofstream("output", std::ios::app)
      << "thrown in a program: exit status " << status << std::endl;
}
