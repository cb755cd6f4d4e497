#ifndef phasefield_core_parser_messages_h
#define phasefield_core_parser_messages_h

#include <deal.II/base/exceptions.h>
#include <sstream>
#include <streambuf>
#include <string>

namespace PhaseField
{
  /**
   * While it exists, what is written to std::cerr is kept instead of
   * printed. deal.II's FunctionParser prints muParser's
   * Message/Formula/Token/Position block to std::cerr before it throws;
   * with this around the parsing, the program's message about the
   * parameter is the only one (parser_message() takes the parts that
   * matter from the kept text). Not thread-safe: std::cerr is global.
   */
  class StderrCapture
  {
  public:
    StderrCapture();

    ~StderrCapture();

    StderrCapture(const StderrCapture &) = delete;
    StderrCapture &
    operator=(const StderrCapture &) = delete;

    /** What was written to std::cerr so far. */
    std::string
    text() const;

  private:
    std::ostringstream captured;
    std::streambuf    *saved;
  };

  /**
   * What muParser said about an expression, for a message naming its
   * parameter: "<muParser's message> (at position <position>)" (without
   * a final period; the position only if the message has none) from the
   * block that deal.II's FunctionParser printed (@p captured, kept by a
   * StderrCapture), or deal.II's text of @p error if that block is not
   * there.
   */
  std::string
  parser_message(const std::string           &captured,
                 const dealii::ExceptionBase &error);
} // namespace PhaseField

#endif
