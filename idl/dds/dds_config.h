#pragma once
// Where the DDS traffic of a process goes. Multi-host deployments use the user's Cyclone config
// (CYCLONEDDS_URI or --dds-config) on --domain; the embedded runner and every test use a
// loopback-only config with a tag of their own, so that two runs never see each other and
// nothing leaves the machine.
#include <string>
#include <vector>

namespace rlpos {

// Which RLpos program a participant is: it decides what its DDS Security identity must be
// allowed to publish. kAny (tests, tools) checks the identity's certificates only.
enum class DdsRole { kAny, kCoordinator, kWorker, kClient };

// "coordinator", "worker", "client" ("any" for kAny): also the default identity name.
const char* RoleName(DdsRole role);

struct DdsOptions {
  int domain = 0;
  std::string config;        // Cyclone XML or file://...; empty: CYCLONEDDS_URI / defaults
  std::string loopback_tag;  // non-empty: loopback-only, discovery tag = this
  std::string security_dir;  // non-empty: DDS Security with the files of `rlpos-campaign security`
  std::string identity;      // identity in security_dir; empty: RoleName(role)
  bool insecure = false;     // accept an unsecured configuration off loopback
  DdsRole role = DdsRole::kAny;
};

// Cyclone XML: network interface lo only (multicast on lo), unicast peer 127.0.0.1, discovery
// tag `tag`, and a short participant lease so that a killed process is noticed in seconds.
// `domain_extra` goes inside <Domain> (DDS Security's <Security> element).
std::string LoopbackConfigXml(const std::string& tag, double lease_s = 2.0,
                              const std::string& domain_extra = "");

// The command-line flags that select the above, in the form every daemon takes them:
// --domain N --loopback TAG | --dds-config XML_OR_FILE, --security DIR --identity NAME,
// --insecure. Empty flags are left out; the role is not a flag (each program has its own).
std::vector<std::string> DdsArgs(const DdsOptions& options);

// Throws std::invalid_argument for a domain outside 0..230, both a config and a tag, an
// identity without a security folder, or an unsecured configuration off loopback without
// `insecure` (secure by default: only --loopback may go without --security).
void CheckDdsOptions(const DdsOptions& options);

}  // namespace rlpos
