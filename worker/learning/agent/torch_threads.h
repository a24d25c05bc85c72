#pragma once
// How many threads libtorch may use for one training or policy.

namespace rlpos {

// One intra-op thread unless the environment names a count (OMP_NUM_THREADS, as Slurm users
// set it from --cpus-per-task). A worker already runs one job per core, and the networks are
// small (64-unit layers, batches of at most 256): on a node with many cores, libtorch's default
// pool of one thread per core in every job would oversubscribe it (docs/benchmarks.md). Returns
// the count in force.
int UseOneTorchThreadUnlessAsked();

}  // namespace rlpos
