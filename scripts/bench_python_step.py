#!/usr/bin/env python3
"""Benchmark: the Python binding's cost per env step. The same env steps the same actions in a
C++ loop (no Python between steps) and from Python (env.step, numpy observations, info dicts),
alternating, `--rounds` times each; prints steps/s both ways and the overhead of Python, per
fidelity. Asserts nothing.

  build/bin/rlpos-python scripts/bench_python_step.py [--scenario FILE]
      [--analytic-steps 20000] [--packet-steps 60] [--rounds 3]
"""
import argparse
import os
import statistics
import time

from rlpos_python import import_rlpos

rlpos = import_rlpos()

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENARIO = os.path.join(HERE, "..", "campaigns", "scenarios", "b.json")
ACTIONS = [0, 2, 4, 1, 3, 5, 6]  # up, forward, left, down, backward, right, stay


def python_steps(env, steps, seed):
    env.reset(seed=seed)
    started = time.perf_counter()
    for i in range(steps):
        _, _, terminated, truncated, _ = env.step(ACTIONS[i % len(ACTIONS)])
        if terminated or truncated:
            env.reset(seed=seed)
    return time.perf_counter() - started


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default=DEFAULT_SCENARIO)
    parser.add_argument("--analytic-steps", type=int, default=20000)
    parser.add_argument("--packet-steps", type=int, default=60)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    print("| fidelity | steps | C++ steps/s | Python steps/s | Python overhead |")
    print("|---|---|---|---|---|")
    for fidelity, steps in (("analytic", args.analytic_steps), ("packet", args.packet_steps)):
        env = rlpos.make(args.scenario, fidelity=fidelity)
        cpp, py = [], []
        for r in range(args.rounds):
            cpp.append(env._env.time_steps(ACTIONS, steps, 1))
            py.append(python_steps(env, steps, 1))
        env.close()
        cpp_s, py_s = statistics.median(cpp), statistics.median(py)
        print("| %s | %d | %.1f | %.1f | %+.1f %% |" % (fidelity, steps, steps / cpp_s,
                                                        steps / py_s, 100 * (py_s / cpp_s - 1)),
              flush=True)


if __name__ == "__main__":
    main()
