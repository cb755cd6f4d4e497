#ifndef phasefield_program_h
#define phasefield_program_h

#include <deal.II/base/parameter_handler.h>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

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

  /**
   * Construct a @p Problem from @p arguments and return what its run()
   * returns. An
   * exception of run() is rethrown only after the problem is destroyed:
   * no destructor of the problem then runs while an exception is in
   * flight, which deal.II's TimerOutput answers with a paragraph about
   * "an uncaught exception" before the program's own message (its
   * output is `never` and its sections are closed, so the destruction
   * needs no communication).
   */
  template <typename Problem, typename... Arguments>
  auto
  run_problem(Arguments &&...arguments)
  {
    using Result = decltype(std::declval<Problem &>().run());
    std::exception_ptr failure;
    std::conditional_t<std::is_void_v<Result>, bool, std::optional<Result>>
      result{};
    {
      std::optional<Problem> problem;
      problem.emplace(std::forward<Arguments>(arguments)...);
      try
        {
          if constexpr (std::is_void_v<Result>)
            problem->run();
          else
            result.emplace(problem->run());
        }
      catch (...)
        {
          failure = std::current_exception();
        }
    }
    if (failure)
      std::rethrow_exception(failure);
    if constexpr (!std::is_void_v<Result>)
      return std::move(*result);
  }
} // namespace PhaseField

#endif
