#include "idl/dds/daemon_command_line.h"

#include <iostream>

#include "common/command_line/parse_error.h"
#include "common/command_line/version_flag.h"
#include "common/logging/log.h"
#include "idl/dds/dds_cli_options.h"
#include "idl/dds/participant.h"
#include "idl/dds/security/security_check.h"

namespace rlpos {

DaemonCommandLine::DaemonCommandLine(std::string program, const std::string& description,
                                     DdsRole role)
    : program_(std::move(program)), app_(description) {
  AddVersionFlag(app_, program_);
  dds_.role = role;
}

void DaemonCommandLine::AddDdsOptions() {
  rlpos::AddDdsOptions(&app_, dds_);
}

std::optional<int> DaemonCommandLine::Parse(int argc, char** argv) {
  app_.add_option("--log-level", log_level_, "error|warning|info|debug")
      ->check(CLI::IsMember({"error", "warning", "info", "debug"}));
  try {
    app_.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return ExitOnParseError(app_, program_, e, 2);
  }
  try {
    SetLogLevel(ParseLogLevel(log_level_));
    PreflightDds(dds_);
  } catch (const std::exception& e) {
    PrintError(e.what());
    return 2;
  }
  return std::nullopt;
}

void DaemonCommandLine::PrintError(const std::string& what) const {
  std::cerr << program_ << ": error: " << what << "\n";
}

int DaemonCommandLine::Run(const std::function<void()>& daemon) const {
  try {
    daemon();
  } catch (const security::SecuritySetupError& e) {
    // A bad identity is bad input, like a bad flag.
    PrintError(e.what());
    return 2;
  } catch (const std::exception& e) {
    PrintError(e.what());
    return 1;
  }
  return 0;
}

}  // namespace rlpos
