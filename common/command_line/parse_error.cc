#include "common/command_line/parse_error.h"

#include <iostream>

namespace rlpos {

std::string ParseErrorLine(const std::string& program, const CLI::ParseError& error) {
  std::string message = error.what();
  for (char& c : message) {
    if (c == '\n' || c == '\r')
      c = ' ';
  }
  while (!message.empty() && message.back() == ' ')
    message.pop_back();
  return program + ": error: " + message + " (see " + program + " --help)";
}

int ExitOnParseError(const CLI::App& app, const std::string& program, const CLI::ParseError& error,
                     int bad_input_code) {
  // Help and version are "errors" with exit code 0 to CLI11: print them its way.
  if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success))
    return app.exit(error);
  std::cerr << ParseErrorLine(program, error) << std::endl;
  return bad_input_code;
}

}  // namespace rlpos
