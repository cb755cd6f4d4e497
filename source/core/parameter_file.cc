#include <algorithm>
#include <cctype>
#include <cstdint>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <phasefield/core/parameters.h>
#include <sstream>
#include <string>
#include <vector>

// Reading a parameter file: the checks before deal.II's ParameterHandler
// reads it (regular files of bounded size, no include cycles).

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * The largest parameter file read (a .prm file is a few kB; the bound
     * keeps `include /dev/zero` or a huge file from being read without end).
     */
    constexpr std::uintmax_t max_parameter_file_bytes = 16u << 20;

    /**
     * Throw an InputError if @p filename (@p role: "" for the file on the
     * command line, or which file includes it) exists but is not a regular
     * file (a directory, a device such as /dev/zero, a FIFO) or is larger
     * than max_parameter_file_bytes. Files that do not exist are left to
     * the caller's message.
     */
    void
    check_parameter_file(const std::string &filename, const std::string &role)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      if (!fs::exists(filename, error))
        return;
      const std::string which =
        "The parameter file <" + filename + ">" +
        (role.empty() ? std::string() : " (" + role + ")");
      if (!fs::is_regular_file(filename, error))
        throw InputError(which +
                         " is not a regular file (a directory, a device or "
                         "a pipe?).");
      if (fs::file_size(filename, error) > max_parameter_file_bytes)
        throw InputError(which + " is larger than " +
                         std::to_string(max_parameter_file_bytes >> 20) +
                         " MiB: not a parameter file.");
    }



    /**
     * Throw an InputError if the parameter file @p filename, included
     * through the chain @p chain (the files that include it, outermost
     * first), includes itself directly or through other files (deal.II's
     * `include` would recurse until the stack overflows). Files that do
     * not exist are left to ParameterHandler's message.
     */
    void
    check_include_cycles(const std::string        &filename,
                         std::vector<std::string> &chain)
    {
      namespace fs = std::filesystem;
      std::error_code   error;
      const std::string canonical = fs::weakly_canonical(filename, error);
      const auto found = std::find(chain.begin(), chain.end(), canonical);
      if (found != chain.end())
        {
          std::string cycle;
          for (auto file = found; file != chain.end(); ++file)
            cycle += "<" + *file + "> includes ";
          throw InputError("The parameter files include each other in a "
                           "cycle: " +
                           cycle + "<" + canonical + ">.");
        }
      if (!chain.empty())
        check_parameter_file(filename, "included by <" + chain.back() + ">");
      std::ifstream file(filename);
      if (!file)
        return;
      chain.push_back(canonical);
      for (std::string line; std::getline(file, line);)
        {
          line = Utilities::trim(line.substr(0, line.find('#')));
          if (line.size() > 7 && line.compare(0, 7, "include") == 0 &&
              std::isspace(static_cast<unsigned char>(line[7])))
            check_include_cycles(Utilities::trim(line.substr(7)), chain);
        }
      chain.pop_back();
    }
  } // namespace



  void
  read_parameter_file(ParameterHandler &prm, const std::string &filename)
  {
    check_parameter_file(filename, "");
    std::ifstream file(filename);
    if (!file)
      throw InputError("Cannot open the parameter file <" + filename + ">.");
    std::vector<std::string> chain;
    check_include_cycles(filename, chain);
    // a UTF-8 byte order mark (editors on Windows write one) is not part
    // of the first line
    std::string       text{std::istreambuf_iterator<char>(file),
                     std::istreambuf_iterator<char>()};
    const std::string byte_order_mark = "\xEF\xBB\xBF";
    if (text.compare(0, byte_order_mark.size(), byte_order_mark) == 0)
      text.erase(0, byte_order_mark.size());
    std::istringstream input(text);
    try
      {
        prm.parse_input(input, filename);
      }
    catch (const ExceptionBase &exc)
      {
        std::ostringstream info;
        exc.print_info(info);
        throw InputError("Error in the parameter file <" + filename + ">:\n" +
                         info.str());
      }
  }
} // namespace PhaseField
