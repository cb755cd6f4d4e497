#include <deal.II/base/mpi.h>
#include <iostream>
#include <phasefield/core/parameters.h>
#include <phasefield/core/program.h>
#include <sstream>

namespace PhaseField
{
  using namespace dealii;

  int
  run_program(int                                            argc,
              char                                         **argv,
              const std::string                             &program_name,
              const std::function<void(ParameterHandler &)> &declare,
              const std::function<void(ParameterHandler &)> &run)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    ParameterHandler prm;
    declare(prm);

    const std::string first = argc > 1 ? argv[1] : "";
    if (argc > 2 || first == "--help" || first == "-h")
      {
        if (root)
          {
            std::cout << "Usage: " << program_name << " <parameter file>\n\n"
                      << "Parameters (with defaults and documentation):\n\n";
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          }
        return (argc == 2) ? 0 : 1;
      }

    try
      {
        if (argc == 2)
          read_parameter_file(prm, first);
        if (root)
          {
            std::cout << (argc == 2 ? "Parameters read from " + first :
                                      "No parameter file given: running "
                                      "the built-in default (see --help)")
                      << ":\n";
            prm.print_parameters(std::cout,
                                 ParameterHandler::ShortPRM |
                                   ParameterHandler::KeepDeclarationOrder);
            std::cout << std::endl;
          }
        run(prm);
      }
    catch (const InputError &error)
      {
        if (root)
          std::cerr << "\n"
                    << program_name << ": input error: " << error.what() << "\n"
                    << std::endl;
        return 2;
      }
    catch (const ExceptionBase &exc)
      {
        if (root)
          {
            std::ostringstream info;
            exc.print_info(info);
            std::cerr << "\n"
                      << program_name << ": error: " << info.str() << std::endl;
          }
        return 1;
      }
    catch (const std::exception &exc)
      {
        if (root)
          std::cerr << "\n"
                    << program_name << ": error: " << exc.what() << std::endl;
        return 1;
      }
    return 0;
  }
} // namespace PhaseField
