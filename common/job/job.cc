#include "common/job/job.h"

#include <stdexcept>

namespace rlpos {

const char* ToString(JobKind kind) {
  switch (kind) {
    case JobKind::kTrain:
      return "train";
    case JobKind::kPosition:
      return "position";
    case JobKind::kEval:
      return "eval";
    case JobKind::kTrack:
      return "track";
  }
  return "?";
}

JobKind ParseJobKind(const std::string& text) {
  if (text == "train")
    return JobKind::kTrain;
  if (text == "position")
    return JobKind::kPosition;
  if (text == "eval")
    return JobKind::kEval;
  if (text == "track")
    return JobKind::kTrack;
  throw std::invalid_argument("unknown job kind \"" + text + "\"");
}

ScenarioOverride ParseOverride(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw std::invalid_argument("expected path=value, got \"" + text + "\"");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

std::string ToString(const ScenarioOverride& o) {
  return o.path + "=" + o.value;
}

}  // namespace rlpos
