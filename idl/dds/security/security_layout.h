#pragma once
// The folder `rlpos-campaign security init DIR` makes, and what each role may do on the wire.
//   DIR/ca_cert.pem                      the CA: identity CA and permissions CA at once
//   DIR/governance.p7s                   the domain's rules, signed by the CA
//   DIR/identities/NAME/cert.pem         NAME's identity certificate (subject
//   CN=NAME,OU=ROLE,O=RLpos) DIR/identities/NAME/key.pem          its private key (mode 0600)
//   DIR/identities/NAME/permissions.p7s  what NAME may publish and subscribe, signed by the CA
//   DIR/private/ca_key.pem               the CA's key: stays on the machine that issues identities
// A host needs ca_cert.pem, governance.p7s and its own identities/NAME, never private/.
#include <string>
#include <vector>

#include "idl/dds/dds_config.h"

namespace rlpos::security {

struct IdentityFiles {
  std::string ca_cert;
  std::string governance;
  std::string cert;
  std::string key;
  std::string permissions;
};

std::string CaCertFile(const std::string& dir);
std::string CaKeyFile(const std::string& dir);
std::string GovernanceFile(const std::string& dir);
std::string IdentityDir(const std::string& dir, const std::string& name);
IdentityFiles FilesOf(const std::string& dir, const std::string& name);

// Throws std::invalid_argument unless `name` is [A-Za-z0-9_-][A-Za-z0-9._-]{0,63}.
void CheckIdentityName(const std::string& name);

// The topics each role writes and reads (kAny: none).
std::vector<std::string> PublishedTopics(DdsRole role);
std::vector<std::string> SubscribedTopics(DdsRole role);

}  // namespace rlpos::security
