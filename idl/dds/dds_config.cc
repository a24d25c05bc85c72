#include "idl/dds/dds_config.h"

#include <cstdio>
#include <stdexcept>

namespace rlpos {

std::string LoopbackConfigXml(const std::string& tag, double lease_s,
                              const std::string& domain_extra) {
  char lease[32];
  std::snprintf(lease, sizeof lease, "%.3fs", lease_s);
  // The tag only holds [A-Za-z0-9._-] (callers make it), so it needs no XML escaping.
  return std::string("<CycloneDDS><Domain Id=\"any\">") +
         "<General><Interfaces><NetworkInterface name=\"lo\" multicast=\"true\"/></Interfaces>"
         "<AllowMulticast>true</AllowMulticast></General>"
         "<Discovery><Tag>" +
         tag +
         "</Tag>"
         "<Peers><Peer Address=\"127.0.0.1\"/></Peers>"
         "<LeaseDuration>" +
         lease + "</LeaseDuration></Discovery>" + domain_extra + "</Domain></CycloneDDS>";
}

const char* RoleName(DdsRole role) {
  switch (role) {
    case DdsRole::kCoordinator:
      return "coordinator";
    case DdsRole::kWorker:
      return "worker";
    case DdsRole::kClient:
      return "client";
    case DdsRole::kAny:
      break;
  }
  return "any";
}

std::vector<std::string> DdsArgs(const DdsOptions& options) {
  std::vector<std::string> args{"--domain", std::to_string(options.domain)};
  if (!options.loopback_tag.empty()) {
    args.insert(args.end(), {"--loopback", options.loopback_tag});
  }
  if (!options.config.empty())
    args.insert(args.end(), {"--dds-config", options.config});
  if (!options.security_dir.empty())
    args.insert(args.end(), {"--security", options.security_dir});
  if (!options.identity.empty())
    args.insert(args.end(), {"--identity", options.identity});
  if (options.insecure)
    args.push_back("--insecure");
  return args;
}

void CheckDdsOptions(const DdsOptions& options) {
  // Cyclone's default port mapping (7400 + 250 * domain) runs out above 232.
  if (options.domain < 0 || options.domain > 230) {
    throw std::invalid_argument("--domain: must be in 0..230, got " +
                                std::to_string(options.domain));
  }
  if (!options.config.empty() && !options.loopback_tag.empty()) {
    throw std::invalid_argument("--loopback and --dds-config exclude each other");
  }
  for (char c : options.loopback_tag) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    if (!ok) {
      throw std::invalid_argument(
          "--loopback: the tag may hold only letters, digits, '.', '_' "
          "and '-', got \"" +
          options.loopback_tag + "\"");
    }
  }
  if (!options.identity.empty() && options.security_dir.empty())
    throw std::invalid_argument("--identity needs --security DIR");
  if (options.insecure && !options.security_dir.empty())
    throw std::invalid_argument("--insecure and --security exclude each other");
  if (options.loopback_tag.empty() && options.security_dir.empty() && !options.insecure) {
    throw std::invalid_argument(
        "DDS off loopback needs --security DIR (make one with `rlpos-campaign security init "
        "DIR`), or --insecure to let any host on the network read and forge RLpos messages");
  }
}

}  // namespace rlpos
