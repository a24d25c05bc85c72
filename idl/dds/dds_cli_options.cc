#include "idl/dds/dds_cli_options.h"

namespace rlpos {

void AddDdsOptions(CLI::App* command, DdsOptions& dds) {
  command->add_option("--domain", dds.domain, "DDS domain id (default 0)")
      ->check(CLI::Range(0, 230));
  command->add_option("--loopback", dds.loopback_tag,
                      "Loopback-only DDS with this discovery tag (as the embedded runner uses)");
  command->add_option("--dds-config", dds.config, "Cyclone DDS XML or file:// URI");
  command
      ->add_option("--security", dds.security_dir,
                   "DDS Security folder made by `rlpos-campaign security init`")
      ->envname("RLPOS_SECURITY");
  command
      ->add_option("--identity", dds.identity,
                   "Identity in the security folder (default: the program's role)")
      ->envname("RLPOS_IDENTITY");
  command->add_flag("--insecure", dds.insecure,
                    "Allow DDS off loopback without --security (anyone on the network can "
                    "read and forge messages)");
}

}  // namespace rlpos
