#ifndef phasefield_program_h
#define phasefield_program_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <string>

namespace PhaseField
{
  /**
   * The common main() of all programs: MPI initialisation, `--help`
   * (prints every parameter with its documentation), reading the .prm
   * file given as the only argument, printing the parsed parameters, and
   * turning every error into a message and a non-zero exit code.
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
