#include <csignal>
#include <deal.II/base/mpi.h>
#include <phasefield/core/stop_request.h>

namespace PhaseField
{
  namespace
  {
    /** The signal that asked to stop, 0 if none. */
    volatile std::sig_atomic_t requested_signal = 0;

    extern "C" void
    request_stop(const int signal)
    {
      if (requested_signal != 0)
        {
          // the second signal: stop now
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      requested_signal = signal;
    }
  } // namespace



  void
  install_stop_handlers()
  {
    std::signal(SIGTERM, request_stop);
    std::signal(SIGINT, request_stop);
    // a closed terminal or ssh session: stop as for SIGTERM, so the lock
    // of the output directory is released and a checkpoint written
    std::signal(SIGHUP, request_stop);
  }



  std::string
  stop_requested(const MPI_Comm mpi_communicator)
  {
    const int signal =
      dealii::Utilities::MPI::max(static_cast<int>(requested_signal),
                                  mpi_communicator);
    if (signal == SIGTERM)
      return "SIGTERM";
    if (signal == SIGINT)
      return "SIGINT";
    if (signal == SIGHUP)
      return "SIGHUP";
    return signal == 0 ? "" : "signal " + std::to_string(signal);
  }
} // namespace PhaseField
