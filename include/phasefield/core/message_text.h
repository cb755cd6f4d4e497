#ifndef phasefield_core_message_text_h
#define phasefield_core_message_text_h

#include <string>

namespace PhaseField
{
  /** The longest text that an error message quotes in full. */
  constexpr std::size_t max_quoted_characters = 200;

  /**
   * @p text for an error message: itself if it has at most
   * max_quoted_characters characters, else its beginning followed by
   * "... (<n> characters)", so that a message about a huge expression
   * stays one paragraph.
   */
  inline std::string
  abbreviated(const std::string &text)
  {
    if (text.size() <= max_quoted_characters)
      return text;
    return text.substr(0, max_quoted_characters) + "... (" +
           std::to_string(text.size()) + " characters)";
  }
} // namespace PhaseField

#endif
