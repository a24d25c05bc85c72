#include "idl/dds/security/security_layout.h"

#include <stdexcept>

#include "idl/dds/topic_names.h"

namespace rlpos::security {

std::string CaCertFile(const std::string& dir) {
  return dir + "/ca_cert.pem";
}
std::string CaKeyFile(const std::string& dir) {
  return dir + "/private/ca_key.pem";
}
std::string GovernanceFile(const std::string& dir) {
  return dir + "/governance.p7s";
}
std::string IdentityDir(const std::string& dir, const std::string& name) {
  return dir + "/identities/" + name;
}

IdentityFiles FilesOf(const std::string& dir, const std::string& name) {
  const std::string identity = IdentityDir(dir, name);
  return {CaCertFile(dir), GovernanceFile(dir), identity + "/cert.pem", identity + "/key.pem",
          identity + "/permissions.p7s"};
}

void CheckIdentityName(const std::string& name) {
  bool ok = !name.empty() && name.size() <= 64 && name[0] != '.';
  for (char c : name) {
    ok = ok && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                c == '.' || c == '_' || c == '-');
  }
  if (!ok) {
    throw std::invalid_argument("identity name \"" + name +
                                "\": use 1-64 letters, digits, '.', '_' or '-', not starting "
                                "with '.'");
  }
}

std::vector<std::string> PublishedTopics(DdsRole role) {
  switch (role) {
    case DdsRole::kCoordinator:
      return {topic::kJobAssignment, topic::kCampaignReply};
    case DdsRole::kWorker:
      return {topic::kWorkerStatus, topic::kJobEvent};
    case DdsRole::kClient:
      return {topic::kCampaignRequest};
    case DdsRole::kAny:
      break;
  }
  return {};
}

std::vector<std::string> SubscribedTopics(DdsRole role) {
  switch (role) {
    case DdsRole::kCoordinator:
      return {topic::kWorkerStatus, topic::kJobEvent, topic::kCampaignRequest};
    case DdsRole::kWorker:
      return {topic::kJobAssignment};
    case DdsRole::kClient:
      return {topic::kCampaignReply};
    case DdsRole::kAny:
      break;
  }
  return {};
}

}  // namespace rlpos::security
