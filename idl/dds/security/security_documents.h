#pragma once
// The DDS Security governance and permissions documents (OMG DDS-Security 1.1 schemas), before
// they are signed.
#include <ctime>
#include <string>

#include "idl/dds/dds_config.h"

namespace rlpos::security {

// Domains 0..230: no unauthenticated participants, join access control, and discovery,
// liveliness, submessages, metadata and payloads of every topic encrypted.
std::string GovernanceXml();

// One grant for `subject` (RFC 2253, as the certificate's) valid over [not_before, not_after]:
// publish and subscribe exactly the role's topics (default partition); deny everything else.
std::string PermissionsXml(const std::string& name, const std::string& subject, DdsRole role,
                           std::time_t not_before, std::time_t not_after);

// "2026-11-23T08:00:00" (UTC): the form the permissions' <validity> needs (a bare date is
// misread).
std::string PermissionsTime(std::time_t t);

}  // namespace rlpos::security
