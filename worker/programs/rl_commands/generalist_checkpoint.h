#pragma once
// The checkpoint of a training across scenarios, in OUT.partial/checkpoint/: the agent's exact
// training state (agent.state) and where the training stood (progress.json). Ctrl-C, then the
// same command, goes on from it and ends with the policy an uninterrupted run gives. A checkpoint
// is written beside the last one and swapped in by renames: a kill leaves the last or the new one.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "worker/learning/agent/ppo_agent.h"
#include "worker/learning/training/generalist_training.h"

namespace rlpos::sim {

struct SavedCheckpoint {
  GeneralistState state;
  std::uint64_t curve_bytes = 0;  // learning_curve.csv's length when it was taken
  double seconds = 0.0;           // training time until then
};

class GeneralistCheckpoint {
 public:
  // `fingerprint`: what the training is (settings, draw, budget); a checkpoint of another is not
  // resumed.
  GeneralistCheckpoint(std::filesystem::path partial, std::string fingerprint);

  // The checkpoint to resume from, if the folder holds one; ConfigError on --out when it is of
  // another training or unreadable (naming the folder and what to do).
  std::optional<SavedCheckpoint> Find() const;
  // Loads the agent's training state of the checkpoint Find() returned.
  void LoadAgent(PpoAgent& agent) const;
  void Save(const GeneralistState& state, const PpoAgent& agent, std::uint64_t curve_bytes,
            double seconds) const;
  void Remove() const;
  bool Exists() const;

 private:
  std::filesystem::path Current() const;  // the folder holding the checkpoint, or empty

  std::filesystem::path dir_;
  std::string fingerprint_;
};

}  // namespace rlpos::sim
