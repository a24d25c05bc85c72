#!/usr/bin/env python3
"""Benchmark of the multi-UAV scenarios: the positioners against each other, and the packet-level cost.

Per scenario (campus2, urban3 by default):
  - baseline, centroid (k-means) and oracle placements from `rlpos-sim position` (analytic reward,
    nLoS, wall time of the search);
  - rl: `rlpos-sim train` per algorithm and seed (analytic), its final placement's reward, the
    ratio to the oracle's and whether it beats the centroid placement; the training wall time;
  - each placement (rl: the first seed of each algorithm) evaluated at packet level over RngRun
    1..R for D s: aggregate throughput, worst UE, Jain's index, mean delay, and the wall time per
    simulated second, beside single-UAV scenario B's cost measured the same way in the same run.
Asserts nothing.

  scripts/bench_multi_uav.py [--build DIR] [--scenarios campus2,urban3] [--algorithms dqn,ppo,sac]
                             [--seeds 1-3] [--runs 3] [--duration 5]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from bench_agents import seeds_of

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)


def run_json(argv):
    started = time.monotonic()
    done = subprocess.run(argv, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("bench_multi_uav: %s failed: %s" % (" ".join(argv[:4]), done.stderr.strip()[-400:]))
    return json.loads(done.stdout), time.monotonic() - started


def placement_of(result):
    return result.get("positions", [result["position"]])


def packet(sim, scenario, placement, runs, duration):
    """Mean metrics over RngRun 1..runs and the wall seconds per simulated second."""
    rows, wall = [], 0.0
    for run in range(1, runs + 1):
        argv = [sim, "eval", "--scenario", scenario, "--run", str(run), "--duration", str(duration),
                "--json"]
        for p in placement:
            argv += ["--position", ",".join("%.17g" % v for v in p)]
        metrics, seconds = run_json(argv)
        rows.append(metrics)
        wall += seconds

    def mean(key):
        values = [m[key] for m in rows if m[key] is not None]
        return statistics.mean(values) if values else float("nan")

    return {"throughput": mean("aggregate_throughput_mbps"), "worst": mean("worst_ue_throughput_mbps"),
            "jain": mean("jain_fairness"), "delay": mean("mean_delay_ms"), "n_los": mean("n_los"),
            "wall_per_sim_s": wall / (runs * duration)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(REPO, "build"))
    parser.add_argument("--scenarios", default="campus2,urban3")
    parser.add_argument("--algorithms", default="dqn,ppo,sac")
    parser.add_argument("--seeds", default="1-3")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--duration", type=float, default=5.0)
    args = parser.parse_args()
    sim = os.path.join(args.build, "bin", "rlpos-sim")
    seeds = seeds_of(args.seeds)

    def scenario_file(name):
        return os.path.join(REPO, "campaigns", "scenarios", name + ".json")

    single = packet(sim, scenario_file("b"), [[50, 35, 10]], args.runs, args.duration)
    print("single-UAV B (4 UEs, 234 Mbit/s offered): %.2f wall s per simulated s" %
          single["wall_per_sim_s"])
    with tempfile.TemporaryDirectory() as work:
        for name in args.scenarios.split(","):
            scenario = scenario_file(name)
            print("\n== %s" % name)
            placements = {}
            print("%-10s %8s %6s %9s %8s" % ("positioner", "reward", "nLoS", "analytic", "wall_s"))
            for positioner in ("baseline", "centroid", "oracle"):
                result, seconds = run_json([sim, "position", "--scenario", scenario, "--positioner",
                                            positioner, "--json"])
                placements[positioner] = (placement_of(result), result["reward"])
                print("%-10s %8.4f %6d %9.1f %8.1f" % (positioner, result["reward"], result["n_los"],
                                                       result["analytic_throughput_mbps"], seconds))
            oracle = placements["oracle"][1]
            centroid = placements["centroid"][1]
            print("\n%-4s %4s %8s %6s %6s %9s %7s" %
                  ("alg", "seed", "reward", "ratio", "nLoS", ">kmeans", "train_s"))
            for algorithm in args.algorithms.split(","):
                ratios = []
                for seed in seeds:
                    out = os.path.join(work, "%s-%s-%d" % (name, algorithm, seed))
                    result, seconds = run_json([sim, "train", "--scenario", scenario, "--fidelity",
                                                "analytic", "--algorithm", algorithm, "--seed",
                                                str(seed), "--out", out, "--json"])
                    ratio = result["reward"] / oracle
                    ratios.append(ratio)
                    if seed == seeds[0]:
                        placements["rl@" + algorithm] = (result["positions"], result["reward"])
                    print("%-4s %4d %8.4f %6.3f %6d %9s %7.1f" %
                          (algorithm, seed, result["reward"], ratio, result["n_los"],
                           "yes" if result["reward"] > centroid else "no", seconds))
                print("%-4s mean ratio %.3f, min %.3f, >= 0.95: %d/%d" %
                      (algorithm, statistics.mean(ratios), min(ratios),
                       sum(r >= 0.95 for r in ratios), len(ratios)))
            print("\npacket level, RngRun 1-%d x %g s:" % (args.runs, args.duration))
            print("%-10s %10s %10s %6s %9s %6s %12s" %
                  ("placement", "thr_Mbps", "worst_UE", "Jain", "delay_ms", "nLoS", "wall/sim_s"))
            for label, (placement, _) in placements.items():
                m = packet(sim, scenario, placement, args.runs, args.duration)
                print("%-10s %10.1f %10.2f %6.3f %9.3f %6.1f %6.2f (%.1fx B)" %
                      (label, m["throughput"], m["worst"], m["jain"], m["delay"], m["n_los"],
                       m["wall_per_sim_s"], m["wall_per_sim_s"] / single["wall_per_sim_s"]))


if __name__ == "__main__":
    main()
