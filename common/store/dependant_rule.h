#pragma once
// What happens to the jobs that wait for a job (its dependants) when it succeeds: a scheduling
// rule, implemented on the coordinator's side (scheduling/placement_binding.h), that
// ResultRecorder applies inside the transaction that records the success.
#include <string>

#include "common/campaign/expansion.h"

namespace rlpos {

class DependantRule {
 public:
  virtual ~DependantRule() = default;
  // Throws std::invalid_argument when the dependants of `job_id` cannot take the placement it
  // produced: the attempt then fails, and nothing of it is written.
  virtual void Check(const std::string& job_id, const Placement& produced) = 0;
  // Gives each dependant of `job_id` its placement from `produced` and releases the ones that
  // were pending.
  virtual void Bind(const std::string& job_id, const Placement& produced) = 0;
};

}  // namespace rlpos
