#!/usr/bin/env python3
"""Benchmark of the RL algorithms against the oracle (analytic fidelity).

Per algorithm, scenario and training seed: trains with `rlpos-sim train --algorithm`, and
compares the final greedy position's analytic reward with the oracle's best (on the grid of the
algorithm's action space: the move step for dqn and ppo, 1 m for sac's displacements). Prints
one row per run and a summary per algorithm and scenario. Asserts nothing.

  scripts/bench_agents.py [--build DIR] [--seeds 1-10] [--algorithms dqn,ppo,sac]
                          [--scenarios a,b,c] [--target 0.95] [--set PATH=VALUE ...]

--scenarios takes shipped names (a, b, c, campus2, ...), scenario files, or a folder of them
(a set written by scripts/generate_scenario_set.sh). Scenarios of several UAVs are judged
against the oracle's coordinate descent, as the multi-UAV figures are.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)


def seeds_of(text):
    first, _, last = text.partition("-")
    return list(range(int(first), int(last or first) + 1))


def run_json(argv):
    done = subprocess.run(argv, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("bench_agents: %s failed: %s" % (" ".join(argv[:3]), done.stderr.strip()[-400:]))
    return json.loads(done.stdout)


def scenario_files(text):
    files = []
    for item in text.split(","):
        if os.path.isdir(item):
            files += sorted(os.path.join(item, f) for f in os.listdir(item) if f.endswith(".json"))
        elif item.endswith(".json"):
            files.append(item)
        else:
            files.append(os.path.join(REPO, "campaigns", "scenarios", item + ".json"))
    return files


def oracle_reward(sim, scenario, algorithm):
    """The best analytic reward on the oracle's grid for the algorithm's action space (no
    packet-level re-scoring: rl is trained and judged at analytic fidelity)."""
    space = "continuous" if algorithm == "sac" else "discrete"
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(sim)), "python"))
    import rlpos  # the build's binding: the oracle without its packet-level re-score
    best = rlpos.oracle(scenario, overrides={"agent.algorithm": algorithm,
                                             "env.action_space": space},
                        packet_candidates=0, top=1)
    return best[0]["analytic_reward"]


def env_steps(folder):
    with open(os.path.join(folder, "learning_curve.csv")) as f:
        next(f)
        return sum(int(row.split(",")[2]) for row in f if row.split(",")[1] == "train")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(REPO, "build"))
    parser.add_argument("--seeds", default="1-10")
    parser.add_argument("--algorithms", default="dqn,ppo,sac")
    parser.add_argument("--scenarios", default="a,b,c")
    parser.add_argument("--target", type=float, default=0.95)
    parser.add_argument("--set", action="append", default=[], metavar="PATH=VALUE",
                        help="a scenario override for every training, e.g. agent.ppo.epochs=4")
    args = parser.parse_args()
    sim = os.path.join(args.build, "bin", "rlpos-sim")
    seeds = seeds_of(args.seeds)
    algorithms = args.algorithms.split(",")
    scenarios = scenario_files(args.scenarios)

    rows = []
    print("%-4s %-22s %4s %8s %8s %6s %5s %7s %7s" %
          ("alg", "sc", "seed", "reward", "oracle", "ratio", "nLoS", "steps", "wall_s"))
    with tempfile.TemporaryDirectory() as work:
        for scenario in scenarios:
            name = os.path.splitext(os.path.basename(scenario))[0]
            oracles = {}
            for algorithm in algorithms:
                space = "continuous" if algorithm == "sac" else "discrete"
                if space not in oracles:
                    oracles[space] = oracle_reward(sim, scenario, algorithm)
                for seed in seeds:
                    out = os.path.join(work, "%s-%s-%d" % (name, algorithm, seed))
                    started = time.monotonic()
                    overrides = [a for o in args.set for a in ("--set", o)]
                    result = run_json([sim, "train", "--scenario", scenario, "--fidelity",
                                       "analytic", "--algorithm", algorithm, "--seed", str(seed),
                                       "--out", out, "--json"] + overrides)
                    wall = time.monotonic() - started
                    row = {"algorithm": algorithm, "scenario": name, "seed": seed,
                           "reward": result["reward"], "oracle": oracles[space],
                           "n_los": result["n_los"], "n_ues": result["n_ues"],
                           "steps": env_steps(out), "wall": wall}
                    row["ratio"] = row["reward"] / row["oracle"]
                    rows.append(row)
                    print("%-4s %-22s %4d %8.4f %8.4f %6.3f %2d/%-2d %7d %7.1f" %
                          (algorithm, name, seed, row["reward"], row["oracle"], row["ratio"],
                           row["n_los"], row["n_ues"], row["steps"], wall), flush=True)

    print("\nsummary (target: reward >= %.0f %% of the oracle's)" % (args.target * 100))
    print("| algorithm | scenario | seeds >= target | mean ratio | min ratio | mean nLoS "
          "| env steps | mean train wall (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for algorithm in algorithms:
        for name in [os.path.splitext(os.path.basename(f))[0] for f in scenarios]:
            group = [r for r in rows if r["algorithm"] == algorithm and r["scenario"] == name]
            if not group:
                continue
            n = len(group)
            print("| %s | %s | %d/%d | %.3f | %.3f | %.1f/%d | %d | %.1f |" % (
                algorithm, name, sum(r["ratio"] >= args.target for r in group), n,
                sum(r["ratio"] for r in group) / n, min(r["ratio"] for r in group),
                sum(r["n_los"] for r in group) / n, group[0]["n_ues"], group[0]["steps"],
                sum(r["wall"] for r in group) / n))


if __name__ == "__main__":
    main()
