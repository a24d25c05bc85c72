#pragma once
// A policy folder as a client sends it with a campaign: the folder as the campaign names it and
// the files the client packed from it (wire/policy_bundle.h). The same struct on the wire
// (idl/dds/messages.h) and in the coordinator's planning (campaign_request.h).
#include <string>
#include <vector>

#include "common/wire/policy_bundle.h"

namespace rlpos {

struct SubmittedPolicy {
  std::string folder;  // as the campaign writes it
  std::vector<PolicyFile> files;
};

}  // namespace rlpos
