#pragma once
// CLI11 reports a bad command line on two lines ("--x: bad" then "Run with --help for more
// information."). Every RLpos program speaks the one-line "PROGRAM: error: ..." format instead.
#include <CLI/CLI.hpp>
#include <string>

namespace rlpos {

// The one line for `error`: "PROGRAM: error: <CLI11's message> (see PROGRAM --help)", on one
// line whatever CLI11's text holds.
std::string ParseErrorLine(const std::string& program, const CLI::ParseError& error);

// Handles what app.parse threw: help and version requests print as CLI11 prints them and give 0;
// an error prints ParseErrorLine on stderr and gives `bad_input_code`.
int ExitOnParseError(const CLI::App& app, const std::string& program, const CLI::ParseError& error,
                     int bad_input_code);

}  // namespace rlpos
