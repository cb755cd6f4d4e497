#ifndef phasefield_core_quiet_timer_output_h
#define phasefield_core_quiet_timer_output_h

#include <deal.II/base/timer.h>
#include <exception>
#include <optional>
#include <phasefield/core/parser_messages.h>

namespace PhaseField
{
  namespace internal
  {
    /**
     * The base of QuietTimerOutput that keeps std::cerr from the moment
     * keep_stderr() is called until it is destroyed, which is after the
     * TimerOutput base of QuietTimerOutput.
     */
    class StderrKeeper
    {
    protected:
      void
      keep_stderr()
      {
        capture.emplace();
      }

      std::optional<StderrCapture> capture;
    };
  } // namespace internal

  /**
   * A dealii::TimerOutput that prints nothing when it is destroyed while
   * an exception is in flight (a problem whose constructor or run()
   * throws). deal.II's TimerOutput then skips its summary and its MPI
   * communication, but prints a paragraph about "an uncaught exception"
   * to std::cerr before the program's own message; here that paragraph
   * goes to a StderrCapture that ends with the object. Otherwise the same
   * as TimerOutput.
   */
  class QuietTimerOutput : private internal::StderrKeeper,
                           public dealii::TimerOutput
  {
  public:
    using dealii::TimerOutput::TimerOutput;

    ~QuietTimerOutput()
    {
      // the TimerOutput base is destroyed after this, the keeper after it
      if (std::uncaught_exceptions() > 0)
        keep_stderr();
    }
  };
} // namespace PhaseField

#endif
