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

// `order` must have passed CheckJobOrder; the scenario it runs is <folder>/scenario.json,
// written by the caller with every setting and override already applied.
std::vector<std::string> SimCommandLine(const JobOrder& order, const std::string& sim_binary,
                                        const std::string& folder);

}  // namespace rlpos
