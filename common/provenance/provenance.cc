#include "common/provenance/provenance.h"

#include "rlpos_build_info.h"

namespace rlpos {

Provenance ThisBuild() {
  Provenance p;
  p.rlpos_version = RLPOS_BUILD_VERSION;
  p.ns3_version = RLPOS_BUILD_NS3_VERSION;
  p.torch_version = RLPOS_BUILD_TORCH_VERSION;
  p.cyclonedds_version = RLPOS_BUILD_CYCLONEDDS_VERSION;
  return p;
}

namespace {

// "ns-3 V, libtorch V, Cyclone DDS V": the libraries a build was made with.
std::string DescribeLibraries(const Provenance& p) {
  return "ns-3 " + p.ns3_version + ", libtorch " + p.torch_version + ", Cyclone DDS " +
         p.cyclonedds_version;
}

}  // namespace

std::string DescribeBuild(const Provenance& p) {
  return "rlpos " + p.rlpos_version + ", " + DescribeLibraries(p);
}

std::string VersionText(const std::string& program) {
  const Provenance p = ThisBuild();
  return program + " " + RLPOS_BUILD_RELEASE + " (commit " + p.rlpos_version + ")\nbuilt with " +
         DescribeLibraries(p);
}

}  // namespace rlpos
