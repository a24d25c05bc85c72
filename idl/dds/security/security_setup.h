#pragma once
// `rlpos-campaign security init DIR` and `add-worker DIR NAME`: a CA, the signed governance,
// and identities with their signed permissions (layout in security_layout.h). Nothing is left
// half-written: each command builds in a temporary sibling and renames it into place.
#include <ctime>
#include <string>

#include "idl/dds/dds_config.h"

namespace rlpos::security {

struct IssueOptions {
  std::time_t now = 0;  // 0: the current time
  int days = 365;       // identity certificates and permissions
  int ca_days = 3650;   // the CA (init only)
};

// Creates DIR (it must not exist, or be empty) with a new CA, governance and the identities
// "coordinator", "worker" and "client". Throws std::runtime_error naming the file and cause.
void InitSecurityDir(const std::string& dir, const IssueOptions& options = {});

// Issues identities/NAME for `role`, signed by DIR's CA (which needs DIR/private/ca_key.pem).
// Throws if NAME exists. Returns the identity's folder.
std::string AddIdentity(const std::string& dir, const std::string& name, DdsRole role,
                        const IssueOptions& options = {});

}  // namespace rlpos::security
