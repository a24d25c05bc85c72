#pragma once
// Where the DDS traffic of a process goes. Multi-host deployments use the user's Cyclone config
// (CYCLONEDDS_URI or --dds-config) on --domain; the embedded runner and every test use a
// loopback-only config with a tag of their own, so that two runs never see each other and
// nothing leaves the machine.
#include <string>
#include <vector>

namespace rlpos {

struct DdsOptions {
  int domain = 0;
  std::string config;        // Cyclone XML or file://...; empty: CYCLONEDDS_URI / defaults
  std::string loopback_tag;  // non-empty: loopback-only, discovery tag = this
};

// Cyclone XML: network interface lo only (multicast on lo), unicast peer 127.0.0.1, discovery
// tag `tag`, and a short participant lease so that a killed process is noticed in seconds.
std::string LoopbackConfigXml(const std::string& tag, double lease_s = 2.0);

// The command-line flags that select the above, in the form every daemon takes them:
// --domain N --loopback TAG | --dds-config XML_OR_FILE. Empty flags are left out.
std::vector<std::string> DdsArgs(const DdsOptions& options);

// Throws std::invalid_argument for a domain outside 0..230 or both a config and a tag.
void CheckDdsOptions(const DdsOptions& options);

}  // namespace rlpos
