#!/usr/bin/env python3
"""PPO's training with its rollouts from one env against several (agent.ppo.num_envs), side by
side: per scenario and training seed, `rlpos-sim train --algorithm ppo` with each num_envs in
turn (analytic fidelity, the defaults otherwise), its wall and CPU seconds (the child's user +
system time: the better guide on a shared machine) and its reward against the oracle's best on
the move grid. Prints one row per training, then per variant: the ratio's median, worst and
runs >= 0.95, and the times' median and worst, with the speed-up against the first variant.
--baseline-build DIR adds a first variant, num_envs 1 with another build's rlpos-sim (an older
commit's, to compare two builds' trainings pair by pair in one run). Asserts nothing.

  scripts/bench_ppo_vector.py --scenarios DIR|FILE,... [--build DIR] [--seeds 1-3]
                              [--num-envs 1,8] [--baseline-build DIR] [--jobs 1]
                              [--set PATH=VALUE ...] [--oracle-cache FILE]

The oracle is `rlpos-sim position --positioner oracle`: the best analytic reward of its
candidates (the top of the analytic grid search). --oracle-cache keeps them between runs, keyed
by the scenario file's bytes (a rebuilt reward model needs a new cache).
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
sys.path.insert(0, HERE)
from bench_agents import (file_digest, load_cache, quantile, save_cache,  # noqa: E402
                          scenario_files, seeds_of)
import hashlib  # noqa: E402


def run(argv):
    """(stdout as JSON, wall s, CPU s: the child's user + system time, by /usr/bin/time)."""
    with tempfile.NamedTemporaryFile("r", suffix=".time") as times:
        started = time.monotonic()
        done = subprocess.run(["/usr/bin/time", "-f", "%U %S", "-o", times.name] + argv,
                              capture_output=True, text=True)
        wall = time.monotonic() - started
        if done.returncode != 0:
            sys.exit("bench_ppo_vector: %s failed: %s" % (" ".join(argv[:3]),
                                                          done.stderr.strip()[-400:]))
        user, system = (float(v) for v in times.read().split()[-2:])
    return json.loads(done.stdout), wall, user + system


def oracle_reward(sim, scenario):
    """The oracle's best analytic reward, or None (with a line on stderr) when `position` fails:
    the scenario's runs are then left out rather than the whole benchmark lost."""
    try:
        result, _, _ = run([sim, "position", "--scenario", scenario, "--positioner", "oracle",
                            "--json"])
    except SystemExit as failure:
        print("bench_ppo_vector: %s left out: %s" % (os.path.basename(scenario), failure),
              file=sys.stderr, flush=True)
        return None
    return max(c["analytic_reward"] for c in result["candidates"])


def train(sim, scenario, seed, num_envs, overrides, work, label):
    name = os.path.splitext(os.path.basename(scenario))[0]
    out = os.path.join(work, "%s-%d-%s" % (name, seed, label))
    result, wall, cpu = run([sim, "train", "--scenario", scenario, "--fidelity", "analytic",
                               "--algorithm", "ppo", "--seed", str(seed), "--out", out,
                               "--json", "--set", "agent.ppo.num_envs=%d" % num_envs]
                              + overrides)
    return result["reward"], wall, cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(os.path.dirname(HERE), "build"))
    parser.add_argument("--scenarios", required=True)
    parser.add_argument("--seeds", default="1-3")
    parser.add_argument("--num-envs", default="1,8")
    parser.add_argument("--baseline-build", metavar="DIR",
                        help="first variant: num_envs 1 with this build's rlpos-sim")
    parser.add_argument("--jobs", type=int, default=1, help="trainings at a time")
    parser.add_argument("--set", action="append", default=[], metavar="PATH=VALUE")
    parser.add_argument("--oracle-cache", metavar="FILE")
    args = parser.parse_args()
    sim = os.path.join(args.build, "bin", "rlpos-sim")
    # (label, rlpos-sim, num_envs)
    variants = [("n%d" % int(v), sim, int(v)) for v in args.num_envs.split(",")]
    if args.baseline_build:
        variants.insert(0, ("baseline", os.path.join(args.baseline_build, "bin", "rlpos-sim"), 1))
    scenarios = scenario_files(args.scenarios)
    overrides = [a for o in args.set for a in ("--set", o)]
    print("load average at start: %.2f %.2f %.2f" % os.getloadavg())
    print("%-22s %4s %8s %8s %8s %6s %7s %7s" %
          ("scenario", "seed", "variant", "reward", "oracle", "ratio", "wall_s", "cpu_s"))
    rows = []
    with tempfile.TemporaryDirectory() as work, \
            concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        cache = load_cache(args.oracle_cache)

        def key(scenario):
            digest = hashlib.sha256()
            file_digest(scenario, digest)
            return digest.hexdigest()

        def cached_oracle(scenario):
            if key(scenario) not in cache:
                reward = oracle_reward(sim, scenario)
                if reward is None:
                    return None  # not cached: a later build may place it
                cache[key(scenario)] = reward
            return cache[key(scenario)]

        oracles = {s: pool.submit(cached_oracle, s) for s in scenarios}
        runs = [(s, seed, v) for s in scenarios for seed in seeds_of(args.seeds)
                for v in variants]
        futures = [pool.submit(train, v[1], s, seed, v[2], overrides, work, v[0])
                   for s, seed, v in runs]
        for (scenario, seed, (label, _, n)), future in zip(runs, futures):
            reward, wall, cpu = future.result()
            oracle = oracles[scenario].result()
            if oracle is None:
                continue
            if args.oracle_cache:
                save_cache(args.oracle_cache, cache)
            row = {"scenario": os.path.splitext(os.path.basename(scenario))[0], "seed": seed,
                   "variant": label, "ratio": reward / oracle, "wall": wall, "cpu": cpu}
            rows.append(row)
            print("%-22s %4d %8s %8.4f %8.4f %6.3f %7.1f %7.1f" %
                  (row["scenario"], seed, label, reward, oracle, row["ratio"], wall, cpu),
                  flush=True)
    print("load average at end: %.2f %.2f %.2f" % os.getloadavg())
    print("\n| variant | runs | median ratio | worst ratio | runs >= 0.95 | median wall s "
          "| worst wall s | median CPU s | worst CPU s | CPU speed-up (median / worst) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    first = None
    for label, _, _ in variants:
        group = [r for r in rows if r["variant"] == label]
        if not group:
            continue
        ratios = sorted(r["ratio"] for r in group)
        walls = sorted(r["wall"] for r in group)
        cpus = sorted(r["cpu"] for r in group)
        if first is None:
            first = {(r["scenario"], r["seed"]): r["cpu"] for r in group}
        speedups = sorted(first[(r["scenario"], r["seed"])] / r["cpu"] for r in group)
        print("| %s | %d | %.3f | %.3f | %d | %.1f | %.1f | %.1f | %.1f | %.2f / %.2f |" % (
            label, len(group), quantile(ratios, 0.5), ratios[0], sum(v >= 0.95 for v in ratios),
            quantile(walls, 0.5), walls[-1], quantile(cpus, 0.5), cpus[-1],
            quantile(speedups, 0.5), speedups[0]))


if __name__ == "__main__":
    main()
