// rlpos-sim's side of the RL module: finds it beside the binary (../lib/rlpos, in a build as in
// an install) and forwards to it; a general PPO policy's placement needs no module
// (worker/learning/policy_folder/general_placement.h).
#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <stdexcept>
#include <string>

#include "worker/learning/policy_folder/general_placement.h"
#include "worker/learning/policy_folder/policy_folder.h"
#include "worker/programs/rlpos_sim/portable_kernels.h"
#include "worker/programs/sim_api/rl_plugin_api.h"

namespace rlpos::sim {
namespace {

std::string ModulePath() {
  char exe[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0)
    throw std::runtime_error("cannot locate the rlpos-sim binary (/proc/self/exe)");
  std::string dir(exe, static_cast<std::size_t>(n));
  dir = dir.substr(0, dir.rfind('/'));
  return dir + "/../lib/rlpos/librlpos_rl_commands.so";
}

const RlCommands& Load() {
  static const RlCommands* commands = [] {
    const std::string path = ModulePath();
    // Before libtorch and OpenBLAS load with the module: they choose their kernels once.
    PinPortableKernels();
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module)
      throw std::runtime_error("cannot load the RL commands: " + std::string(dlerror()));
    auto entry = reinterpret_cast<const RlCommands* (*)()>(dlsym(module, "rlpos_rl_commands_v5"));
    if (!entry)
      throw std::runtime_error(path + ": no rlpos_rl_commands_v5 entry point");
    return entry();
  }();
  return *commands;
}

}  // namespace

int RunTrain(const CommonOptions& options, const TrainOptions& train) {
  return Load().train(options, train);
}

Placement RlPlacement(const CommonOptions& options, const std::string& policy) {
  // A policy for any scenario of ours flies without the module: libtorch's load is most of a
  // placement's time.
  if (!policy.empty()) {
    const PolicyFolder folder = ReadPolicyFolder(policy);
    if (FliesWithoutLibtorch(folder))
      return GeneralPlacement(folder, options);
  }
  return Load().policy_placement(options, policy);
}

TrackDecision RlTrackDecision(const CommonOptions& options, const std::string& policy) {
  if (!policy.empty()) {
    const PolicyFolder folder = ReadPolicyFolder(policy);
    if (FliesWithoutLibtorch(folder))
      return GeneralTrack(folder, options);
  }
  return Load().policy_track(options, policy);
}

}  // namespace rlpos::sim
