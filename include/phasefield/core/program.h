#ifndef phasefield_program_h
#define phasefield_program_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <string>

namespace PhaseField
{
  /**
   * The common main() of all programs: MPI initialisation, `--help`
   * (prints the usage and every parameter with its documentation),
   * reading the .prm file given as the only non-option argument (none:
   * the defaults), then applying every `--set "Subsection/Name=value"`
   * in order (nested subsections joined by `/`, top-level parameters
   * without one), printing the parameters, and turning every error into
   * a message and an exit status: 0 on success, 2 for an InputError
   * (this includes a malformed command line and an unknown or invalid
   * `--set`), 1 for any other error.
   *
   * @p declare declares the parameters; @p run parses them and runs the
   * program.
   */
  int
  run_program(int                argc,
              char             **argv,
              const std::string &program_name,
              const std::function<void(dealii::ParameterHandler &)> &declare,
              const std::function<void(dealii::ParameterHandler &)> &run);
} // namespace PhaseField

#endif
