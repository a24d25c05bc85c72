#include "common/command_line/version_flag.h"

#include "common/provenance/provenance.h"

namespace rlpos {

void AddVersionFlag(CLI::App& app, const std::string& program) {
  app.set_version_flag("--version", VersionText(program), "Print the version and exit");
}

}  // namespace rlpos
