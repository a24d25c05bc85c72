#!/usr/bin/env python3
"""Benchmark: analytic env steps per second, one env and batched, and memory per env.

For each scenario (B, a generated 12-UE urban scenario and a three-UAV scenario by default),
side by side in one run:
  - one env stepped in a C++ loop (no Python between steps) and the same env from Python
    (rlpos.make, env.step);
  - rlpos.make_vec at each --num-envs (default 1, 8, 64, 256), random actions drawn beforehand;
  - memory per env: the process's resident memory before and after building --memory-envs
    analytic envs with make_vec and stepping each --memory-steps times, divided by their number.
Each figure is the median of --rounds timings. Asserts nothing.

  build/bin/rlpos-python scripts/bench_vector_env.py [--scenario FILE ...]
      [--steps 20000] [--batched-steps 400000] [--num-envs 1,8,64,256] [--rounds 3]
      [--threads N] [--memory-envs 256] [--memory-steps 2000]
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

from bench_common import cpu_model
from rlpos_python import import_rlpos

rlpos = import_rlpos()
import numpy as np  # noqa: E402 (after the check of the interpreter)


HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
ACTIONS = [0, 2, 4, 1, 3, 5, 6]


def resident_kib():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("/proc/self/status has no VmRSS")


def generated_scenario(build, folder, seed, ues):
    """A generated urban scenario with `ues` UEs, written by rlpos-sim generate."""
    path = os.path.join(folder, "urban-%dues-s%d.json" % (ues, seed))
    subprocess.run([os.path.join(build, "bin", "rlpos-sim"), "generate", "--seed", str(seed),
                    "--style", "urban", "--ues", str(ues), "--out", path], check=True)
    return path


def single_env(scenario, steps, rounds):
    """(C++ steps/s, Python steps/s) of one analytic env, the same actions both ways."""
    env = rlpos.make(scenario, fidelity="analytic", seed=1)
    discrete = hasattr(env.action_space, "n")
    cpp, py = [], []
    for _ in range(rounds):
        if discrete:
            cpp.append(env._env.time_steps(ACTIONS, steps, 1))
        env.reset(seed=1)
        actions = [ACTIONS[i % len(ACTIONS)] for i in range(steps)]
        started = time.perf_counter()
        for action in actions:
            _, _, terminated, truncated, _ = env.step(action)
            if terminated or truncated:
                env.reset()
        py.append(time.perf_counter() - started)
    env.close()
    cpp_rate = steps / statistics.median(cpp) if cpp else float("nan")
    return cpp_rate, steps / statistics.median(py)


def batched(scenario, num_envs, total_steps, rounds, threads):
    """make_vec's env steps per second at num_envs (total_steps env steps a round)."""
    env = rlpos.make_vec(scenario, num_envs=num_envs, seed=1, threads=threads)
    calls = max(1, total_steps // num_envs)
    rng = np.random.default_rng(1)
    space = env.action_space
    if hasattr(space, "nvec"):
        actions = rng.integers(0, space.nvec[0], size=(calls, num_envs), dtype=np.int64)
    else:
        low, high = space.low[0], space.high[0]
        actions = rng.uniform(low, high, size=(calls,) + space.shape).astype(space.dtype)
    env.reset(seed=1)
    env.step(actions[0])  # threads started, buffers allocated
    times = []
    for _ in range(rounds):
        started = time.perf_counter()
        for a in actions:
            env.step(a)
        times.append(time.perf_counter() - started)
    env.close()
    return calls * num_envs / statistics.median(times)


def memory_per_env(scenario, num_envs, steps):
    """KiB of resident memory per analytic env after `steps` steps of each, measured in a fresh
    process (memory freed by earlier figures would otherwise be reused and hide the growth)."""
    child = subprocess.run([sys.executable, os.path.abspath(__file__), "--memory-of", scenario,
                            "--memory-envs", str(num_envs), "--memory-steps", str(steps)],
                           check=True, capture_output=True, text=True)
    return float(child.stdout)


def measure_memory_here(scenario, num_envs, steps):
    rlpos.make(scenario, fidelity="analytic").close()  # the module's own first-use allocations
    before = resident_kib()
    env = rlpos.make_vec(scenario, num_envs=num_envs, seed=1)
    env.reset(seed=1)
    rng = np.random.default_rng(2)
    space = env.action_space
    for _ in range(steps):
        if hasattr(space, "nvec"):
            env.step(rng.integers(0, space.nvec[0], size=num_envs, dtype=np.int64))
        else:
            env.step(rng.uniform(space.low[0], space.high[0],
                                 size=space.shape).astype(space.dtype))
    grown = resident_kib() - before
    env.close()
    return grown / num_envs


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--scenario", action="append",
                        help="a scenario file (repeatable); default: B, a generated 12-UE urban "
                             "scenario (seed 90000) and campaigns/scenarios/urban3.json")
    parser.add_argument("--steps", type=int, default=20000, help="steps of the one-env figures")
    parser.add_argument("--batched-steps", type=int, default=400000,
                        help="env steps a round of each batched figure")
    parser.add_argument("--num-envs", default="1,8,64,256")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--threads", type=int, default=None,
                        help="make_vec's threads (default: its own, min(cores, num_envs))")
    parser.add_argument("--memory-envs", type=int, default=256)
    parser.add_argument("--memory-steps", type=int, default=2000)
    parser.add_argument("--memory-of", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.memory_of:
        print(measure_memory_here(args.memory_of, args.memory_envs, args.memory_steps))
        return
    try:
        sizes = [int(n) for n in args.num_envs.split(",")]
    except ValueError:
        sys.exit("bench_vector_env.py: error: --num-envs: expected numbers separated by commas, "
                 "got %r" % args.num_envs)

    with tempfile.TemporaryDirectory() as folder:
        scenarios = args.scenario or [
            os.path.join(ROOT, "campaigns", "scenarios", "b.json"),
            generated_scenario(args.build, folder, 90000, 12),
            os.path.join(ROOT, "campaigns", "scenarios", "urban3.json"),
        ]
        print("%d cores, %s; %d rounds, medians" % (os.cpu_count(), cpu_model(), args.rounds))
        print()
        header = ["scenario", "one env, C++", "one env, Python"]
        header += ["make_vec N=%d" % n for n in sizes] + ["KiB per env"]
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        for scenario in scenarios:
            cpp, py = single_env(scenario, args.steps, args.rounds)
            row = [os.path.basename(scenario), "%.0f" % cpp, "%.0f" % py]
            for n in sizes:
                row.append("%.0f" % batched(scenario, n, args.batched_steps, args.rounds,
                                            args.threads))
            row.append("%.0f" % memory_per_env(scenario, args.memory_envs, args.memory_steps))
            print("| " + " | ".join(row) + " |", flush=True)


if __name__ == "__main__":
    main()
