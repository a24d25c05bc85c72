#pragma once
// Cyclone DDS's <Security> configuration for a checked identity: the three plugins of Debian's
// libddsc (found at build time; RLPOS_DDS_SECURITY_PLUGIN_DIR), and the identity's files as
// file: URIs.
#include <string>

#include "idl/dds/security/security_layout.h"

namespace rlpos::security {

// The folder of libdds_security_{auth,ac,crypto}.so, or "" to let the loader search.
std::string PluginDir();

// The <Security> element, to go inside a <Domain> the caller writes. Throws std::runtime_error
// when the plugins are not where the build found them.
std::string SecurityElementXml(const IdentityFiles& files);

}  // namespace rlpos::security
