#!/usr/bin/env python3
"""Benchmark: the memory of analytic envs. Builds `--envs` envs of one scenario in this process,
steps each `--steps` seeded random actions (resets included, as episodes end), and prints the
growth of the process's resident memory per env: after building them, and after stepping them
(which fills each env's bounded memo of analytic states, worker/env/uav_env/placement_memo.h).
Asserts nothing.

  build/bin/rlpos-python scripts/bench_env_memory.py [--scenario FILE]
      [--envs 200] [--steps 10000]
"""
import argparse
import os
import random

from rlpos_python import import_rlpos

rlpos = import_rlpos()

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENARIO = os.path.join(HERE, "..", "campaigns", "scenarios", "b.json")


def rss_kib():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS in /proc/self/status")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default=DEFAULT_SCENARIO)
    parser.add_argument("--envs", type=int, default=200)
    parser.add_argument("--steps", type=int, default=10000)
    args = parser.parse_args()
    if args.envs < 1 or args.steps < 0:
        parser.error("--envs must be at least 1 and --steps at least 0")
    # One env first, so that what every env shares (libraries, ns-3's type registry) is counted
    # before the baseline.
    first = rlpos.make(args.scenario, fidelity="analytic")
    first.reset(seed=1)
    first.step(0)
    before = rss_kib()
    envs = [rlpos.make(args.scenario, fidelity="analytic") for _ in range(args.envs)]
    built = rss_kib()
    rng = random.Random(1)
    for k, env in enumerate(envs):
        env.reset(seed=k + 1)
        n = env.action_space.n
        for _ in range(args.steps):
            _, _, terminated, truncated, _ = env.step(rng.randrange(n))
            if terminated or truncated:
                env.reset()
    stepped = rss_kib()
    print("| scenario | envs | steps each | KiB per env, built | KiB per env, after the steps |")
    print("|---|---|---|---|---|")
    print("| %s | %d | %d | %.0f | %.0f |" % (os.path.basename(args.scenario), args.envs,
                                               args.steps, (built - before) / args.envs,
                                               (stepped - before) / args.envs))
    for env in envs + [first]:
        env.close()


if __name__ == "__main__":
    main()
