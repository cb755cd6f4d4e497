#include <deal.II/base/mpi.h>
#include <iostream>
#include <phasefield/core/blas_kernels.h>
#include <phasefield/core/file_io.h>
#include <phasefield/core/mesh_size.h>
#include <phasefield/core/message_text.h>
#include <phasefield/core/parameters.h>
#include <phasefield/core/program.h>
#include <phasefield/core/stop_request.h>
#include <sstream>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** Exit status of a successful run. */
    constexpr int exit_success = 0;
    /** Exit status of a run stopped by an error that is not an InputError. */
    constexpr int exit_error = 1;
    /** Exit status of a run stopped by an InputError. */
    constexpr int exit_input_error = 2;

    /**
     * Removes the output directories' lock files (release_output_locks())
     * when it goes out of scope: at every return of run_program().
     */
    struct OutputLockRelease
    {
      ~OutputLockRelease()
      {
        release_output_locks();
      }
    };

    /** What the command line asks for. */
    struct CommandLine
    {
      bool                     help = false;
      std::string              parameter_file;
      std::vector<std::string> settings;
    };

    std::string
    usage(const std::string &program_name)
    {
      return "Usage: " + program_name +
             " [--help] [--set \"Subsection/Name=value\"]... "
             "[<parameter file>]";
    }

    /** Parse the arguments; a malformed command line is an InputError. */
    CommandLine
    parse_command_line(const int          argc,
                       char             **argv,
                       const std::string &program_name)
    {
      CommandLine command_line;
      for (int i = 1; i < argc; ++i)
        {
          const std::string argument = argv[i];
          if (argument == "--help" || argument == "-h")
            command_line.help = true;
          else if (argument == "--set" && i + 1 < argc)
            command_line.settings.emplace_back(argv[++i]);
          else if (argument.rfind("--set=", 0) == 0)
            command_line.settings.push_back(argument.substr(6));
          else if (!argument.empty() && argument[0] == '-')
            throw InputError("Unknown or incomplete option <" + argument +
                             "> on the command line. " + usage(program_name));
          else if (command_line.parameter_file.empty())
            command_line.parameter_file = argument;
          else
            throw InputError("More than one parameter file on the command "
                             "line (<" +
                             command_line.parameter_file + "> and <" +
                             argument + ">). " + usage(program_name));
        }
      return command_line;
    }

    /** @p text without leading and trailing white space. */
    std::string
    trim(const std::string &text)
    {
      const std::size_t first = text.find_first_not_of(" \t");
      if (first == std::string::npos)
        return "";
      return text.substr(first, text.find_last_not_of(" \t") - first + 1);
    }

    /**
     * Apply one `--set "Subsection/Name=value"` to @p prm: an unknown
     * subsection or parameter, or a value that violates the pattern of the
     * parameter, is an InputError that names it.
     */
    void
    apply_setting(ParameterHandler &prm, const std::string &setting)
    {
      const std::size_t equals = setting.find('=');
      if (equals == std::string::npos)
        throw InputError("--set <" + setting +
                         "> is not of the form \"Subsection/Name=value\".");
      const std::string        key = trim(setting.substr(0, equals));
      std::vector<std::string> path;
      std::istringstream       parts(key);
      for (std::string part; std::getline(parts, part, '/');)
        path.push_back(trim(part));
      if (path.empty() || path.back().empty() || key.back() == '/')
        throw InputError("--set <" + setting +
                         "> names no parameter before the \"=\"; use the "
                         "form \"Subsection/Name=value\".");
      const std::string name  = path.back();
      const std::string value = trim(setting.substr(equals + 1));
      path.pop_back();
      std::string full_name;
      for (const std::string &subsection : path)
        full_name += subsection + " / ";
      full_name += name;
      if (!path.empty() && !prm.subsection_path_exists(path))
        throw InputError("--set <" + setting + ">: there is no subsection <" +
                         full_name.substr(0, full_name.rfind(" / ")) +
                         "> (see --help).");
      for (const std::string &subsection : path)
        prm.enter_subsection(subsection);
      std::string error;
      try
        {
          prm.set(name, value);
        }
      catch (const ParameterHandler::ExcEntryUndeclared &)
        {
          error = "there is no parameter <" + full_name + "> (see --help)";
        }
      catch (const ExceptionBase &)
        {
          error = "the value <" + value +
                  "> does not match the pattern of the parameter <" +
                  full_name + ">";
        }
      for (std::size_t i = 0; i < path.size(); ++i)
        prm.leave_subsection();
      if (!error.empty())
        throw InputError("--set <" + setting + ">: " + error + ".");
    }

    /** Print the usage, the options and every parameter. */
    void
    print_help(ParameterHandler &prm, const std::string &program_name)
    {
      std::cout
        << usage(program_name) << "\n\n"
        << "Reads the parameter file (without one: the built-in defaults "
           "below) and runs.\n"
           "--set \"Subsection/Name=value\" sets one parameter after the "
           "parameter file\n"
           "has been read, or on the defaults without a file. It may be "
           "repeated (later\n"
           "ones win); nested subsections are joined by '/', top-level "
           "parameters have\n"
           "none, e.g. --set \"Mesh/Finest level=5\" --set \"Output "
           "directory=out\".\n"
           "Exit status: 0 on success, 2 for invalid input (parameter "
           "file, --set,\n"
           "command line, input files, a checkpoint that fails "
           "verification, an output\n"
           "directory in use by another run), 1 for any other error "
           "(e.g. Newton's method\n"
           "failed, a failed write, a stop by SIGTERM, SIGINT or SIGHUP).\n\n"
        << "Parameters (with defaults and documentation):\n\n";
      prm.print_parameters(std::cout, ParameterHandler::PRM);
    }

    /** Read the file and the settings of @p command_line, print the result. */
    void
    read_parameters(ParameterHandler  &prm,
                    const CommandLine &command_line,
                    const bool         root)
    {
      if (!command_line.parameter_file.empty())
        read_parameter_file(prm, command_line.parameter_file);
      for (const std::string &setting : command_line.settings)
        apply_setting(prm, setting);
      if (!root)
        return;
      std::cout << (command_line.parameter_file.empty() ?
                      "No parameter file given: running the built-in "
                      "default (see --help)" :
                      "Parameters read from " + command_line.parameter_file);
      for (const std::string &setting : command_line.settings)
        std::cout << "\n  with --set \"" << abbreviated(setting) << "\"";
      std::cout << ":\n";
      // the parameters one line each, a huge value (an expression of
      // hundreds of kilobytes) abbreviated as in the error messages
      std::ostringstream parameters;
      prm.print_parameters(parameters,
                           ParameterHandler::ShortPRM |
                             ParameterHandler::KeepDeclarationOrder);
      std::istringstream lines(parameters.str());
      for (std::string line; std::getline(lines, line);)
        std::cout << abbreviated(line) << '\n';
      std::cout << std::endl;
    }
  } // namespace



  int
  run_program(int                                            argc,
              char                                         **argv,
              const std::string                             &program_name,
              const std::function<void(ParameterHandler &)> &declare,
              const std::function<void(ParameterHandler &)> &run)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const OutputLockRelease          release_locks_at_return;
    install_stop_handlers();
    MeshSize::determine_memory_per_rank(MPI_COMM_WORLD);
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const std::string blas_message = select_blas_kernels();
    if (root && !blas_message.empty())
      std::cout << blas_message << "\n" << std::endl;
    ParameterHandler prm;
    declare(prm);

    try
      {
        const CommandLine command_line =
          parse_command_line(argc, argv, program_name);
        if (command_line.help)
          {
            if (root)
              print_help(prm, program_name);
            return exit_success;
          }
        read_parameters(prm, command_line, root);
        run(prm);
      }
    catch (const InputError &error)
      {
        if (root)
          std::cerr << "\n"
                    << program_name << ": input error: " << error.what() << "\n"
                    << std::endl;
        return exit_input_error;
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
        return exit_error;
      }
    catch (const std::exception &exc)
      {
        if (root)
          std::cerr << "\n"
                    << program_name << ": error: " << exc.what() << std::endl;
        return exit_error;
      }
    return exit_success;
  }
} // namespace PhaseField
