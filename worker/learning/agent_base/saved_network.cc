#include "worker/learning/agent_base/saved_network.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "worker/learning/agent_base/saved_tensors.h"

namespace rlpos {
namespace {

bool StartsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::vector<SavedTensor> Read(const std::string& file) {
  if (!std::filesystem::exists(file))
    throw std::runtime_error(file + ": no such policy file");
  try {
    return ReadSavedTensors(file);
  } catch (const std::runtime_error&) {
    throw std::runtime_error(file + ": not a policy file of this network");
  }
}

bool HasUeEncoder(const std::vector<SavedTensor>& tensors) {
  return std::any_of(tensors.begin(), tensors.end(),
                     [](const SavedTensor& t) { return StartsWith(t.name, "phi."); });
}

// The tensors named PREFIX*, in order, as `net`'s layers: false, `net` untouched, when they are
// not its shape.
bool Fill(const std::vector<SavedTensor>& tensors, const std::string& prefix, DenseNetwork& net) {
  std::vector<const SavedTensor*> mine;
  for (const SavedTensor& t : tensors) {
    if (StartsWith(t.name, prefix))
      mine.push_back(&t);
  }
  if (static_cast<int>(mine.size()) != 2 * net.LayerCount())
    return false;
  for (int l = 0; l < net.LayerCount(); ++l) {
    const SavedTensor& w = *mine[static_cast<std::size_t>(2 * l)];
    const SavedTensor& b = *mine[static_cast<std::size_t>(2 * l + 1)];
    const std::int64_t in = net.LayerInputs(l);
    const std::int64_t out = net.LayerOutputs(l);
    if (!EndsWith(w.name, ".weight") || !EndsWith(b.name, ".bias") ||
        w.sizes != std::vector<std::int64_t>{out, in} || b.sizes != std::vector<std::int64_t>{out})
      return false;
  }
  for (int l = 0; l < net.LayerCount(); ++l) {
    net.SetLayer(l, mine[static_cast<std::size_t>(2 * l)]->values.data(),
                 mine[static_cast<std::size_t>(2 * l + 1)]->values.data());
  }
  return true;
}

}  // namespace

void LoadSavedNetwork(const std::string& file, DenseNetwork& net) {
  const std::vector<SavedTensor> tensors = Read(file);
  if (HasUeEncoder(tensors)) {
    throw std::runtime_error(file +
                             ": the policy's network has a UE encoder (agent.ue_encoder), "
                             "the scenario's agent has none");
  }
  if (!Fill(tensors, "", net)) {
    throw std::runtime_error(file +
                             ": the policy's network shape differs from the scenario's "
                             "(observations, actions or agent.hidden changed)");
  }
}

void LoadSavedNetwork(const std::string& file, UeSetNetwork& net) {
  const std::vector<SavedTensor> tensors = Read(file);
  if (!HasUeEncoder(tensors)) {
    throw std::runtime_error(file +
                             ": the policy's network has no UE encoder, the scenario's agent "
                             "sets agent.ue_encoder");
  }
  DenseNetwork encoder(net.EncoderSizes(), true);
  DenseNetwork head(net.HeadSizes());
  const bool counted = std::all_of(tensors.begin(), tensors.end(), [](const SavedTensor& t) {
    return StartsWith(t.name, "phi.") || StartsWith(t.name, "rho.");
  });
  if (!counted || !Fill(tensors, "phi.", encoder) || !Fill(tensors, "rho.", head)) {
    throw std::runtime_error(file +
                             ": the policy's network shape differs from the scenario's "
                             "(observations, actions, agent.hidden or agent.ue_encoder changed)");
  }
  // ue_set_module.cc's layout: phi's parameters, then rho's.
  std::vector<float>& p = net.Parameters();
  std::copy(encoder.Parameters().begin(), encoder.Parameters().end(), p.begin());
  std::copy(head.Parameters().begin(), head.Parameters().end(),
            p.begin() + static_cast<long>(net.EncoderParameterCount()));
}

}  // namespace rlpos
