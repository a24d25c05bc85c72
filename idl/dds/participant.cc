#include "dds/participant.h"

#include <dds/dds.h>

namespace rlpos {

std::int32_t CheckDds(std::int32_t rc, const std::string& what) {
  if (rc < 0)
    throw DdsError(what + ": " + dds_strretcode(rc));
  return rc;
}

Participant::Participant(const DdsOptions& options) : options_(options) {
  CheckDdsOptions(options);
  const auto domain = static_cast<dds_domainid_t>(options.domain);
  std::string config = options.config;
  if (!options.loopback_tag.empty())
    config = LoopbackConfigXml(options.loopback_tag);
  if (!config.empty()) {
    domain_ = CheckDds(dds_create_domain(domain, config.c_str()),
                       "DDS domain " + std::to_string(options.domain) + " (check --dds-config)");
  }
  participant_ = dds_create_participant(domain, nullptr, nullptr);
  if (participant_ < 0) {
    const std::int32_t rc = participant_;
    if (domain_ > 0)
      dds_delete(domain_);
    CheckDds(rc, "DDS participant on domain " + std::to_string(options.domain));
  }
}

Participant::~Participant() {
  dds_delete(participant_);
  if (domain_ > 0)
    dds_delete(domain_);
}

}  // namespace rlpos
