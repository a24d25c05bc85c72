#include "dds/dds_cli_options.h"

namespace rlpos {

void AddDdsOptions(CLI::App* command, DdsOptions& dds) {
  command->add_option("--domain", dds.domain, "DDS domain id (default 0)")
      ->check(CLI::Range(0, 230));
  command->add_option("--loopback", dds.loopback_tag,
                      "Loopback-only DDS with this discovery tag (as the embedded runner uses)");
  command->add_option("--dds-config", dds.config, "Cyclone DDS XML or file:// URI");
}

}  // namespace rlpos
