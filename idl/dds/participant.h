#pragma once
// RAII over a Cyclone DDS domain and participant: one per process. Deleting the participant
// deletes every reader and writer made from it (and, for the worker status, disposes it: the
// coordinator then knows the worker stopped rather than died).
#include <cstdint>
#include <stdexcept>
#include <string>

#include "idl/dds/dds_config.h"

namespace rlpos {

class DdsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws DdsError naming `what` and Cyclone's reason when `rc` < 0; returns rc otherwise.
std::int32_t CheckDds(std::int32_t rc, const std::string& what);

// What Participant would refuse before any DDS call: the options (CheckDdsOptions) and, with
// --security, the identity (security::CheckIdentity; throws SecuritySetupError naming the file).
// Programs call it before they write anything.
void PreflightDds(const DdsOptions& options);

class Participant {
 public:
  explicit Participant(const DdsOptions& options);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  std::int32_t handle() const { return participant_; }
  const DdsOptions& options() const { return options_; }

 private:
  DdsOptions options_;
  std::int32_t domain_ = 0;  // 0: none created (the default domain from CYCLONEDDS_URI)
  std::int32_t participant_ = 0;
};

}  // namespace rlpos
