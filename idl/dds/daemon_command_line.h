#pragma once
// The command line rlpos-coordinator and rlpos-worker share around their own flags: the DDS
// flags, --log-level last, the checks before anything starts, and the exit codes: 0 stopped by
// SIGTERM/SIGINT (or --help), 1 runtime failure, 2 bad input.
#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>

#include "idl/dds/dds_config.h"

namespace rlpos {

class DaemonCommandLine {
 public:
  // `program` prefixes the error lines ("rlpos-worker: error: ...").
  DaemonCommandLine(std::string program, const std::string& description, DdsRole role);

  CLI::App& app() { return app_; }
  const DdsOptions& dds() const { return dds_; }
  // The DDS flags (AddDdsOptions), where the daemon's help shows them.
  void AddDdsOptions();
  // Adds --log-level, parses argv, sets the log level and checks the DDS options (PreflightDds).
  // Returns the exit code to leave with (0 after --help; 2 on bad input, said on stderr), or
  // nullopt to go on.
  std::optional<int> Parse(int argc, char** argv);
  // Prints "<program>: error: <what>" on stderr.
  void PrintError(const std::string& what) const;
  // Runs the daemon until it returns: 0; 2 on a bad security identity (bad input, like a bad
  // flag); 1 on any other failure. Errors are said on stderr.
  int Run(const std::function<void()>& daemon) const;

 private:
  std::string program_;
  CLI::App app_;
  DdsOptions dds_;
  std::string log_level_ = "info";
};

}  // namespace rlpos
