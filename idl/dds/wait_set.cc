#include "idl/dds/wait_set.h"

#include <dds/dds.h>

namespace rlpos {

WaitSet::WaitSet(Participant& participant) {
  waitset_ = CheckDds(dds_create_waitset(participant.handle()), "DDS wait set");
}

WaitSet::~WaitSet() {
  dds_delete(waitset_);
}

void WaitSet::Attach(std::int32_t reader) {
  // The condition belongs to the reader, so it goes when the reader does.
  const dds_entity_t condition =
      CheckDds(dds_create_readcondition(reader, DDS_ANY_STATE), "DDS read condition");
  CheckDds(dds_waitset_attach(waitset_, condition, condition), "attaching a read condition");
}

bool WaitSet::Wait(double timeout_s) {
  const dds_return_t n =
      dds_waitset_wait(waitset_, nullptr, 0, static_cast<dds_duration_t>(timeout_s * 1e9));
  CheckDds(n, "waiting for DDS data");
  return n > 0;
}

}  // namespace rlpos
