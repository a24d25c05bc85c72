#pragma once
// A scenario file as a client sends it with a campaign: the name the campaign gives it and the
// JSON text the client read. The same struct on the wire (idl/dds/messages.h) and in the
// coordinator's planning (campaign_request.h).
#include <string>

namespace rlpos {

struct SubmittedScenario {
  std::string file;      // as the campaign writes it
  std::string document;  // JSON text
};

}  // namespace rlpos
