#pragma once
// Bounds of what crosses the network. idl/rlpos_messages.idl declares the same bounds on its
// strings and sequences (Cyclone drops a sample that exceeds them); the validators check them
// again, so that a message decoded by any means is held to them.
#include <cstddef>

namespace rlpos::wire {

constexpr std::size_t kMaxIdLength = 256;    // job ids, request ids
constexpr std::size_t kMaxNameLength = 128;  // worker ids, hosts, scenario names
constexpr std::size_t kMaxCampaignIdLength = 64;
constexpr std::size_t kMaxScenarioDocument = 262144;  // bytes of one scenario JSON
constexpr std::size_t kMaxOverrides = 64;
constexpr std::size_t kMaxUavPositions = 8;  // an eval's placement: one per UAV (kMaxUavs)
constexpr std::size_t kMaxOverridePath = 128;
constexpr std::size_t kMaxOverrideValue = 4096;
constexpr std::size_t kMaxResultJson = 262144;
constexpr std::size_t kMaxArtifacts = 8;                 // files with one result
constexpr std::size_t kMaxArtifactBytes = 4 * 1048576;   // one file
constexpr std::size_t kMaxArtifactsTotal = 8 * 1048576;  // all files of one result
constexpr std::size_t kMaxMessage = 1024;                // error and progress lines
constexpr std::size_t kMaxCampaignJson = 65536;
constexpr std::size_t kMaxCampaignScenarios = 32;
constexpr std::size_t kMaxScenarioFileName = 512;
constexpr std::size_t kMaxWorkerJobs = 1024;           // job keys in one worker status
constexpr std::size_t kMaxJsonDepth = 64;              // nesting of any JSON from the wire
constexpr std::size_t kMaxPolicyFiles = 5;             // PolicyFileNames()
constexpr std::size_t kMaxPolicyFileBytes = 16777216;  // kMaxPolicyBytes: one file, all of them
constexpr std::size_t kMaxPolicyFileName = 64;
constexpr std::size_t kMaxPolicyFolders = 4;  // kMaxCampaignPolicies
constexpr int kMaxAttempt = 1000000;
constexpr int kMaxSlots = 1024;

}  // namespace rlpos::wire
