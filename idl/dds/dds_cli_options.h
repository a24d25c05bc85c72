#pragma once
// The DDS flags every RLpos program takes in the same form: --domain N, --loopback TAG,
// --dds-config XML_OR_FILE, --security DIR (or RLPOS_SECURITY), --identity NAME (or
// RLPOS_IDENTITY), --insecure. The caller sets the role.
#include <CLI/CLI.hpp>

#include "idl/dds/dds_config.h"

namespace rlpos {

void AddDdsOptions(CLI::App* command, DdsOptions& dds);

}  // namespace rlpos
