#pragma once
// --version on every RLpos program: the release, the commit and the versions it was built with.
#include <CLI/CLI.hpp>
#include <string>

namespace rlpos {

// Adds --version to `app`; ExitOnParseError prints it and gives 0.
void AddVersionFlag(CLI::App& app, const std::string& program);

}  // namespace rlpos
