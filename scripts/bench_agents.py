#!/usr/bin/env python3
"""Benchmark of the RL algorithms against the oracle (analytic fidelity).

Per algorithm, scenario and training seed: trains with `rlpos-sim train --algorithm`, and
compares the final greedy position's analytic reward with the oracle's best (on the grid of the
algorithm's action space: the move step for dqn and ppo, 1 m for sac's displacements). Prints
one row per run, a summary per algorithm and scenario, and one per algorithm and UAV count
(median, P10, worst, share at the target). Asserts nothing.

  build/bin/rlpos-python scripts/bench_agents.py [--build DIR] [--seeds 1-10]
      [--algorithms dqn,ppo,sac] [--scenarios a,b,c] [--target 0.95] [--jobs N]
      [--set PATH=VALUE ...] [--oracle-cache FILE]

(rlpos-python: the Python the build's binding is for, which the oracles run on; with --build DIR,
DIR/bin/rlpos-python.)

--scenarios takes shipped names (a, b, c, campus2, ...), scenario files, or a folder of them
(a set written by scripts/generate_scenario_set.sh). Scenarios of several UAVs are judged
against the oracle's coordinate descent, as the multi-UAV figures are.

--oracle-cache FILE keeps the oracles' rewards between runs (sac's 1 m grid costs as much as a
training), keyed by the scenario file's bytes, the action space and the bytes of the build's
Python binding and the rlpos libraries it loads: a rebuilt reward model misses the cache. --set
overrides do not reach the oracle, so they do not enter the key.
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from rlpos_python import import_rlpos  # noqa: E402
from oracle_cache import (OracleCacheError, binding_identity, load_cache,  # noqa: E402
                          oracle_key, save_cache)


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


# Run in a process of its own, so that oracles share the pool with the trainings.
ORACLE_PROGRAM = """
import json, sys
sys.path.insert(0, sys.argv[1])
import rlpos  # the build's binding: the oracle without its packet-level re-score
best = rlpos.oracle(sys.argv[2], overrides={"agent.algorithm": sys.argv[3],
                                            "env.action_space": sys.argv[4]},
                    packet_candidates=0, top=1)
print(json.dumps({"reward": best[0]["analytic_reward"]}))
"""


def space_of(algorithm):
    return "continuous" if algorithm == "sac" else "discrete"


def oracle_reward(sim, scenario, algorithm):
    """The best analytic reward on the oracle's grid for the algorithm's action space (no
    packet-level re-scoring: rl is trained and judged at analytic fidelity)."""
    binding = os.path.join(os.path.dirname(os.path.dirname(sim)), "python")
    return run_json([sys.executable, "-c", ORACLE_PROGRAM, binding, scenario, algorithm,
                     space_of(algorithm)])["reward"]


def env_steps(folder):
    with open(os.path.join(folder, "learning_curve.csv")) as f:
        next(f)
        return sum(int(row.split(",")[2]) for row in f if row.split(",")[1] == "train")


def uav_count(scenario):
    with open(scenario) as f:
        document = json.load(f)
    return len(document["uavs"]) if "uavs" in document else 1


def quantile(sorted_values, q):
    """The q-quantile, linear between order statistics (as the campaign report's optimality
    section)."""
    position = q * (len(sorted_values) - 1)
    low = int(position)
    high = min(low + 1, len(sorted_values) - 1)
    return sorted_values[low] + (position - low) * (sorted_values[high] - sorted_values[low])


def train_one(sim, scenario, algorithm, seed, overrides, work):
    name = os.path.splitext(os.path.basename(scenario))[0]
    out = os.path.join(work, "%s-%s-%d" % (name, algorithm, seed))
    started = time.monotonic()
    result = run_json([sim, "train", "--scenario", scenario, "--fidelity", "analytic",
                       "--algorithm", algorithm, "--seed", str(seed), "--out", out, "--json"]
                      + overrides)
    return result, env_steps(out), time.monotonic() - started


def print_summaries(rows, algorithms, names, target):
    print("\nsummary (target: reward >= %.0f %% of the oracle's)" % (target * 100))
    print("| algorithm | scenario | seeds >= target | mean ratio | min ratio | mean nLoS "
          "| env steps | mean train wall (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for algorithm in algorithms:
        for name in names:
            group = [r for r in rows if r["algorithm"] == algorithm and r["scenario"] == name]
            if not group:
                continue
            n = len(group)
            print("| %s | %s | %d/%d | %.3f | %.3f | %.1f/%d | %d | %.1f |" % (
                algorithm, name, sum(r["ratio"] >= target for r in group), n,
                sum(r["ratio"] for r in group) / n, min(r["ratio"] for r in group),
                sum(r["n_los"] for r in group) / n, group[0]["n_ues"], group[0]["steps"],
                sum(r["wall"] for r in group) / n))
    print("\nper algorithm and UAV count")
    print("| algorithm | UAVs | runs | median | P10 | worst | runs >= %.2f | mean wall (s) "
          "| max wall (s) |" % target)
    print("|---|---|---|---|---|---|---|---|---|")
    counts = sorted({r["uavs"] for r in rows})
    for algorithm in algorithms:
        # Each UAV count, then (with several) all of the algorithm's runs: what the target judges.
        for uavs in counts + (["all"] if len(counts) > 1 else []):
            group = [r for r in rows if r["algorithm"] == algorithm and uavs in (r["uavs"], "all")]
            if not group:
                continue
            ratios = sorted(r["ratio"] for r in group)
            walls = [r["wall"] for r in group]
            print("| %s | %s | %d | %.3f | %.3f | %.3f | %d (%.0f %%) | %.1f | %.1f |" % (
                algorithm, uavs, len(group), quantile(ratios, 0.5), quantile(ratios, 0.1),
                ratios[0], sum(v >= target for v in ratios),
                100.0 * sum(v >= target for v in ratios) / len(ratios),
                sum(walls) / len(walls), max(walls)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(REPO, "build"))
    parser.add_argument("--seeds", default="1-10")
    parser.add_argument("--algorithms", default="dqn,ppo,sac")
    parser.add_argument("--scenarios", default="a,b,c")
    parser.add_argument("--target", type=float, default=0.95)
    parser.add_argument("--jobs", type=int, default=1,
                        help="trainings at a time (each is one process); wall times are per "
                             "training, so they grow when the jobs share too few cores")
    parser.add_argument("--set", action="append", default=[], metavar="PATH=VALUE",
                        help="a scenario override for every training, e.g. agent.ppo.epochs=4")
    parser.add_argument("--oracle-cache", metavar="FILE",
                        help="oracle rewards kept between runs (created if missing)")
    args = parser.parse_args()
    sim = os.path.join(args.build, "bin", "rlpos-sim")
    seeds = seeds_of(args.seeds)
    algorithms = args.algorithms.split(",")
    scenarios = scenario_files(args.scenarios)
    overrides = [a for o in args.set for a in ("--set", o)]
    try:
        cache = load_cache(args.oracle_cache)
        identity = binding_identity(os.path.dirname(os.path.dirname(sim))) \
            if args.oracle_cache else ""
    except OracleCacheError as e:
        sys.exit("bench_agents: %s" % e)
    import_rlpos(args.build)  # the oracles' processes run this interpreter with the build's rlpos

    rows = []
    print("%-4s %-22s %4s %8s %8s %6s %5s %7s %7s" %
          ("alg", "sc", "seed", "reward", "oracle", "ratio", "nLoS", "steps", "wall_s"))
    with tempfile.TemporaryDirectory() as work, \
            concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        # One oracle per scenario and action space, queued first: the 1 m grid of sac's is
        # as slow as a training, so it runs in the pool rather than before it.
        oracles = {}  # (scenario, space): a future, or the cached reward
        for scenario in scenarios:
            for algorithm in algorithms:
                key = (scenario, space_of(algorithm))
                if key in oracles:
                    continue
                cached = cache.get(oracle_key(scenario, key[1], identity))
                oracles[key] = cached if cached is not None else pool.submit(
                    oracle_reward, sim, scenario, algorithm)
        runs = [(scenario, algorithm, seed) for scenario in scenarios
                for algorithm in algorithms for seed in seeds]
        futures = [pool.submit(train_one, sim, scenario, algorithm, seed, overrides, work)
                   for scenario, algorithm, seed in runs]

        def harvest(wait_for=None):
            """Takes in the oracles done by now (and waits for wait_for's); caches new ones."""
            new = False
            for (scenario, space), oracle in oracles.items():
                if isinstance(oracle, concurrent.futures.Future) and (
                        oracle.done() or (scenario, space) == wait_for):
                    oracles[(scenario, space)] = oracle.result()
                    cache[oracle_key(scenario, space, identity)] = oracles[(scenario, space)]
                    new = True
            if new and args.oracle_cache:
                save_cache(args.oracle_cache, cache)

        for (scenario, algorithm, seed), future in zip(runs, futures):
            result, steps, wall = future.result()
            harvest(wait_for=(scenario, space_of(algorithm)))
            oracle = oracles[(scenario, space_of(algorithm))]
            row = {"algorithm": algorithm, "scenario": os.path.splitext(
                       os.path.basename(scenario))[0], "seed": seed,
                   "uavs": uav_count(scenario), "reward": result["reward"], "oracle": oracle,
                   "n_los": result["n_los"], "n_ues": result["n_ues"], "steps": steps,
                   "wall": wall}
            row["ratio"] = row["reward"] / row["oracle"]
            rows.append(row)
            print("%-4s %-22s %4d %8.4f %8.4f %6.3f %2d/%-2d %7d %7.1f" %
                  (algorithm, row["scenario"], seed, row["reward"], oracle, row["ratio"],
                   row["n_los"], row["n_ues"], steps, wall), flush=True)
    names = [os.path.splitext(os.path.basename(f))[0] for f in scenarios]
    print_summaries(rows, algorithms, names, args.target)


if __name__ == "__main__":
    main()
