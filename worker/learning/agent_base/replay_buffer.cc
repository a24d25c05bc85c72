#include "worker/learning/agent_base/replay_buffer.h"

#include <stdexcept>

namespace rlpos {

ReplayBuffer::ReplayBuffer(std::size_t capacity) : capacity_(capacity) {
  if (capacity == 0)
    throw std::invalid_argument("replay buffer capacity must be positive");
}

void ReplayBuffer::Add(Transition t) {
  if (items_.size() < capacity_) {
    items_.push_back(std::move(t));
    return;
  }
  items_[next_] = std::move(t);
  next_ = (next_ + 1) % capacity_;
}

std::vector<std::size_t> ReplayBuffer::SampleIndices(std::size_t batch,
                                                     std::mt19937_64& rng) const {
  if (items_.empty())
    throw std::logic_error("sampling an empty replay buffer");
  std::uniform_int_distribution<std::size_t> pick(0, items_.size() - 1);
  std::vector<std::size_t> indices(batch);
  for (auto& i : indices)
    i = pick(rng);
  return indices;
}

}  // namespace rlpos
