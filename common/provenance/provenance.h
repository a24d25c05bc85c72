#pragma once
// Where a result came from: the host that ran it, the build (rlpos `git describe` and the ns-3,
// libtorch and Cyclone DDS versions it was built with) and the sha256 of the exact scenario
// document it ran. A worker sends it with each result; the store keeps it on the job's row.
#include <string>

namespace rlpos {

struct Provenance {
  std::string host;
  std::string rlpos_version, ns3_version, torch_version, cyclonedds_version;
  std::string scenario_sha256;  // 64 lowercase hex digits, or empty
};

// This build's versions (host and scenario left empty).
Provenance ThisBuild();

// "rlpos V, ns-3 V, libtorch V, Cyclone DDS V": one build, for warnings about mixed builds.
std::string DescribeBuild(const Provenance& p);

// What PROGRAM --version prints: "PROGRAM RELEASE (commit DESCRIBE)" and the versions it was
// built with on a second line.
std::string VersionText(const std::string& program);

}  // namespace rlpos
