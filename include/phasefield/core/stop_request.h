#ifndef phasefield_core_stop_request_h
#define phasefield_core_stop_request_h

#include <deal.II/base/mpi.h>
#include <stdexcept>
#include <string>

namespace PhaseField
{
  /**
   * Thrown on every rank when a run stops at a step boundary because of
   * SIGTERM, SIGINT or SIGHUP (stop_requested()); run_program() prints its message
   * and exits with status 1.
   */
  class StopRequest : public std::runtime_error
  {
  public:
    explicit StopRequest(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * Install the handlers of SIGTERM, SIGINT and SIGHUP: the first one only sets a
   * flag that the time loop reads at the next step boundary
   * (stop_requested()); a second one ends the process at once (the
   * default action).
   */
  void
  install_stop_handlers();

  /**
   * The name of the signal that asked this process or any rank of
   * @p mpi_communicator to stop ("SIGTERM", "SIGINT", "SIGHUP"), empty if none.
   * Collective, so that all ranks stop at the same step.
   */
  std::string
  stop_requested(const MPI_Comm mpi_communicator);
} // namespace PhaseField

#endif
