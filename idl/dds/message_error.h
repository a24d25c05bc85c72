#pragma once
// The one error of converting a message between its C++ struct (dds/messages.h) and its C type
// (rlpos_messages.h), in either direction: a field over its IDL bound, a text with a NUL byte, an
// enum value the IDL does not know. Writer::Write throws it; Reader::Take records its what() in
// Received::decode_error, so that one malformed sample is dropped and the others are kept.
#include <string>

#include "idl/dds/participant.h"

namespace rlpos {

class MessageError : public DdsError {
 public:
  // what() is "<field>: <problem>", one line.
  MessageError(const std::string& field, const std::string& problem)
      : DdsError(field + ": " + problem), field_(field) {}

  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

}  // namespace rlpos
