#pragma once
// The only place where a job becomes a command line: the worker's own rlpos-sim, the attempt's
// own folder, and numbers it formats itself from a validated order. Nothing of the order is
// copied into the command line as text, and no setting: every setting is in the scenario file.
#include <string>
#include <vector>

#include "common/wire/job_order.h"

namespace rlpos {

// The attempt's files, inside its folder.
inline const char kScenarioFileName[] = "scenario.json";  // the effective scenario
inline const char kOutFolderName[] = "out";               // train: policy and learning curve

// Where the worker keeps the named policies its jobs fly, inside its work folder:
// <work_dir>/policies/<sha256> (wire/policy_bundle_files.h), a name no job folder has.
std::string WorkerPoliciesDir(const std::string& work_dir);

// `order` must have passed CheckJobOrder; the scenario it runs is <folder>/scenario.json,
// written by the caller with every setting and override already applied. A named policy's
// position job flies the policy unpacked at `policy_dir` (the worker's own folder for it).
std::vector<std::string> SimCommandLine(const JobOrder& order, const std::string& sim_binary,
                                        const std::string& folder,
                                        const std::string& policy_dir = "");

}  // namespace rlpos
