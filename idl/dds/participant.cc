#include "idl/dds/participant.h"

#include <dds/dds.h>

#include <cstdio>
#include <ctime>

#include "idl/dds/security/security_check.h"
#include "idl/dds/security/security_config.h"

namespace rlpos {

std::int32_t CheckDds(std::int32_t rc, const std::string& what) {
  if (rc < 0)
    throw DdsError(what + ": " + dds_strretcode(rc));
  return rc;
}

namespace {

std::string IdentityName(const DdsOptions& options) {
  return options.identity.empty() ? RoleName(options.role) : options.identity;
}

}  // namespace

void PreflightDds(const DdsOptions& options) {
  CheckDdsOptions(options);
  if (!options.security_dir.empty()) {
    security::CheckIdentity(options.security_dir, IdentityName(options), options.role,
                            std::time(nullptr));
  }
}

Participant::Participant(const DdsOptions& options) : options_(options) {
  CheckDdsOptions(options);
  const auto domain = static_cast<dds_domainid_t>(options.domain);
  std::string config = options.config;
  std::string security;  // the <Security> element, empty when unsecured
  if (!options.security_dir.empty()) {
    security = security::SecurityElementXml(security::CheckIdentity(
        options.security_dir, IdentityName(options), options.role, std::time(nullptr)));
  } else if (options.insecure) {
    std::fprintf(stderr,
                 "warning: --insecure: DDS without authentication; any host that reaches this "
                 "network can read RLpos messages and forge them\n");
  }
  if (!options.loopback_tag.empty()) {
    config = LoopbackConfigXml(options.loopback_tag, 2.0, security);
  } else if (!security.empty()) {
    // Cyclone merges a comma-separated list of configurations, later ones adding to earlier.
    const std::string element =
        "<CycloneDDS><Domain Id=\"any\">" + security + "</Domain></CycloneDDS>";
    config = config.empty() ? element : config + "," + element;
  }
  if (!config.empty()) {
    domain_ = CheckDds(dds_create_domain(domain, config.c_str()),
                       "DDS domain " + std::to_string(options.domain) + " (check --dds-config)");
  }
  participant_ = dds_create_participant(domain, nullptr, nullptr);
  if (participant_ < 0) {
    const std::int32_t rc = participant_;
    if (domain_ > 0)
      dds_delete(domain_);
    CheckDds(rc,
             "DDS participant on domain " + std::to_string(options.domain) +
                 (security.empty() ? "" : " (DDS Security refused it: Cyclone's reason is above)"));
  }
}

Participant::~Participant() {
  dds_delete(participant_);
  if (domain_ > 0)
    dds_delete(domain_);
}

}  // namespace rlpos
