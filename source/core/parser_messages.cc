#include <iostream>
#include <phasefield/core/parser_messages.h>

namespace PhaseField
{
  namespace
  {
    /** The text between `<` and `>` of the line starting @p key in @p text. */
    std::string
    field(const std::string &text, const std::string &key)
    {
      const std::size_t line = text.find(key);
      if (line == std::string::npos)
        return "";
      const std::size_t open  = text.find('<', line);
      const std::size_t close = text.find(">\n", open);
      if (open == std::string::npos || close == std::string::npos)
        return "";
      return text.substr(open + 1, close - open - 1);
    }
  } // namespace



  StderrCapture::StderrCapture()
    : saved(std::cerr.rdbuf(captured.rdbuf()))
  {}



  StderrCapture::~StderrCapture()
  {
    std::cerr.rdbuf(saved);
  }



  std::string
  StderrCapture::text() const
  {
    return captured.str();
  }



  std::string
  parser_message(const std::string           &captured,
                 const dealii::ExceptionBase &error)
  {
    std::string       message  = field(captured, "Message:");
    const std::string position = field(captured, "Position:");
    if (!message.empty() && message.back() == '.')
      message.pop_back();
    if (!message.empty())
      return message + (position.empty() ||
                            message.find("position") != std::string::npos ?
                          "" :
                          " (at position " + position + ")");
    std::ostringstream info;
    error.print_info(info);
    return info.str();
  }
} // namespace PhaseField
