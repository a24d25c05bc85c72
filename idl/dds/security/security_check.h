#pragma once
// Checks an identity before Cyclone DDS loads it, so that a bad file is reported by name and
// cause ("expired", "wrong CA", "subject mismatch", "not allowed to publish ...") rather than
// as Cyclone's bare "Error" at participant creation.
#include <ctime>
#include <stdexcept>
#include <string>

#include "idl/dds/dds_config.h"
#include "idl/dds/security/security_layout.h"

namespace rlpos::security {

class SecuritySetupError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The identity NAME of DIR with absolute paths, after checking: every file present and
// readable; the CA and the certificate valid at `now`, the certificate issued by the CA and
// matching its key; governance and permissions signed by the CA; the permissions' subject equal
// to the certificate's, valid at `now`, and allowing what `role` publishes and subscribes.
// Throws SecuritySetupError with one line naming the file and the cause.
IdentityFiles CheckIdentity(const std::string& dir, const std::string& name, DdsRole role,
                            std::time_t now);

}  // namespace rlpos::security
