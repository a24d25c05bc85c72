#pragma once
// The DDS flags every RLpos program takes in the same form: --domain N, --loopback TAG,
// --dds-config XML_OR_FILE.
#include <CLI/CLI.hpp>

#include "dds/dds_config.h"

namespace rlpos {

void AddDdsOptions(CLI::App* command, DdsOptions& dds);

}  // namespace rlpos
