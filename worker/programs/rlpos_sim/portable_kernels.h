#pragma once
// The same trained policy on every x86-64 CPU. libtorch, OpenBLAS and oneDNN each pick their
// kernels by the CPU they find when they load (AVX-512, AVX2, SSE...), and kernels of different
// widths sum floats in different orders: the same training then gives other weights on another
// CPU, so a train job retried on another worker of a cluster would give another policy. Before
// the RL module loads them, rlpos-sim pins the baseline kernels that every x86-64 CPU runs.

namespace rlpos::sim {

// Sets libtorch's ATEN_CPU_CAPABILITY, OpenBLAS' OPENBLAS_CORETYPE and oneDNN's
// ONEDNN_MAX_CPU_ISA / DNNL_MAX_CPU_ISA, overriding the environment's own values; unless
// RLPOS_NATIVE_KERNELS=1, which keeps the CPU's own kernels (a policy is then reproducible only
// on CPUs of the same kind). Must run before libtorch and OpenBLAS are loaded: they read these
// once, when they start.
void PinPortableKernels();

}  // namespace rlpos::sim
