#pragma once
// How many threads libtorch may use for one training or policy.

namespace rlpos {

// One intra-op thread unless the environment names a count (OMP_NUM_THREADS, as Slurm users
// set it from --cpus-per-task). The networks are small (64-unit layers, batches of at most
// 256): libtorch's pool costs more in wake-ups than it saves, and a campaign already runs one
// job per core. Returns the count in force.
int UseOneTorchThreadUnlessAsked();

}  // namespace rlpos
