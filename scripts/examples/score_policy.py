#!/usr/bin/env python3
"""Scores a Python policy at packet level: flies it in the analytic env, then evaluates its
final position with ns-3 (rlpos.evaluate, as rlpos-sim eval) over several RngRuns, beside the
scenario's baseline position. Replace `policy` with your own.

  build/bin/rlpos-python scripts/examples/score_policy.py [--scenario FILE]
      [--runs 3] [--duration 5]
"""
import argparse
import os
import statistics

try:
    import numpy as np
    import rlpos
except ImportError as error:  # a python3 other than the binding's (pyenv, conda) comes first
    raise SystemExit(f"{error}: run this with build/bin/rlpos-python, the Python rlpos is built for")

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENARIO = os.path.join(HERE, "..", "..", "campaigns", "scenarios", "b.json")


def policy(observation, info, moves, rng):
    """Climb while some UE is out of sight, then drift among the moves that keep every UE in
    sight (observation: x, y, z, n_los)."""
    allowed = [m for m, ok in zip(moves, info.get("action_mask", [1] * len(moves))) if ok]
    n_ues = len(info["snr_db"])
    if observation[3] < n_ues:
        wanted = "up" if "up" in allowed else rng.choice(allowed)
    else:
        wanted = "stay"
    return moves.index(wanted)


def fly(scenario, seed):
    env = rlpos.make(scenario, fidelity="analytic", seed=seed)
    rng = np.random.default_rng(seed)
    observation, info = env.reset()
    start, done = info["position"], False
    while not done:
        action = policy(observation, info, env.moves, rng)
        observation, reward, terminated, truncated, info = env.step(action)
        done = terminated or truncated
    env.close()  # gives ns-3 back for the evaluations
    return start, info["position"], reward


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default=DEFAULT_SCENARIO)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--duration", type=float, default=5.0)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    baseline, final, reward = fly(args.scenario, args.seed)
    print("policy's final position %s (analytic reward %.4f)" % (final, reward))
    print("%-9s %-22s %5s %12s %10s" % ("position", "", "nLoS", "Mbit/s", "delay ms"))
    for name, position in (("baseline", baseline), ("policy", final)):
        results = [rlpos.evaluate(args.scenario, position, run=run, duration=args.duration)
                   for run in range(1, args.runs + 1)]
        throughput = [r["aggregate_throughput_mbps"] for r in results]
        delays = [r["mean_delay_ms"] for r in results if r["mean_delay_ms"] is not None]
        print("%-9s %-22s %2d/%-2d %6.1f +-%4.1f %10.1f" % (
            name, "(%g, %g, %g)" % tuple(position), results[0]["n_los"], results[0]["n_ues"],
            statistics.mean(throughput), statistics.pstdev(throughput),
            statistics.mean(delays) if delays else float("nan")))


if __name__ == "__main__":
    main()
