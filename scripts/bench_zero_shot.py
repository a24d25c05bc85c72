#!/usr/bin/env python3
"""Zero-shot placement: a policy for any scenario against the oracle, on scenarios it never saw.

For every scenario of --scenarios (a set from scripts/generate_scenario_set.sh; --uavs keeps those
with that many UAVs, by the set's index.tsv), the policy places the UAVs with
`rlpos-sim position --positioner rl --policy DIR` (loading the policy and flying it greedy from
the baseline to the best step of its flight, the whole process timed), and the oracle with
`rlpos.oracle(packet_candidates=0)` (the best point of the analytic grid search, timed). Both
are scored by the analytic model. Beside them, the best cell of the coarse map the policy
observes ("coverage", its env.coverage_map from the policy's scenario.json): what flying straight
to the map's best would give, so that the policy's own part can be told from the map's. Prints
one row per scenario (rewards, ratios to the oracle, seconds) and the summary the acceptance of a
policy for any scenario reads: median and P10 of the ratio, the share of scenarios at or above
0.95, those under 0.8, the worst case and the slowest placement.

  build/bin/rlpos-python scripts/bench_zero_shot.py --policy DIR --scenarios DIR [--uavs 1]
      [--build DIR] [--jobs 2] [--csv FILE] [--oracle-cache FILE]

(rlpos-python: the Python the build's binding is for; with --build DIR, DIR/bin/rlpos-python.)

--oracle-cache FILE keeps the oracles' rewards between runs (coordinate descent takes seconds to
minutes per scenario of several UAVs, and comparing policies on one set asks for the same ones),
keyed as scripts/bench_agents.py keys them (scripts/oracle_cache.py). A cached oracle is not
timed: its row shows "cached" and the summary times the others.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from bench_common import write_csv  # noqa: E402
from rlpos_python import import_rlpos  # noqa: E402
from oracle_cache import (OracleCacheError, binding_identity, load_cache,  # noqa: E402
                          oracle_key, save_cache)

# The oracle of the scenario's own settings (rlpos.oracle without overrides), in the cache's keys.
ORACLE_KIND = "scenario"


def fail(message):
    print("bench_zero_shot: %s" % message, file=sys.stderr)
    sys.exit(2)


def scenarios_of(folder, uavs):
    index = os.path.join(folder, "index.tsv")
    if not os.path.exists(index):
        fail("%s has no index.tsv (write the set with scripts/generate_scenario_set.sh)" % folder)
    with open(index) as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    return [os.path.join(folder, r["file"]) for r in rows if uavs is None or int(r["uavs"]) == uavs]


def placed(sim, policy, scenario):
    started = time.monotonic()
    done = subprocess.run([sim, "position", "--scenario", scenario, "--positioner", "rl",
                           "--policy", policy, "--json"], capture_output=True, text=True)
    wall = time.monotonic() - started
    if done.returncode != 0:
        fail("%s: %s" % (os.path.basename(scenario), done.stderr.strip()))
    return json.loads(done.stdout)["reward"], wall


def oracle(rlpos, scenario):
    started = time.monotonic()
    best = rlpos.oracle(scenario, packet_candidates=0, top=1)[0]
    return best["analytic_reward"], time.monotonic() - started


def map_best(rlpos, scenario, cells):
    """The best reward of the coarse map ("coverage") at the baseline."""
    with open(scenario) as f:
        weights = json.load(f).get("env", {}).get("reward", {})
    bound = max(1e-9, sum(max(0.0, weights.get(w, d)) for w, d in
                          (("w1", 0.8), ("w2", 0.2), ("w3", 0.0))))
    env = rlpos.make(scenario, fidelity="analytic",
                     overrides={"env.observations": ["coverage"], "env.coverage_map": cells})
    observation, _ = env.reset(seed=1)
    return float(max(observation[:cells * cells])) * bound


def percentile(values, share):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(share * (len(ordered) - 1) + 0.5))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--policy", required=True, help="policy folder (rlpos-sim train --generated)")
    parser.add_argument("--scenarios", required=True, help="a set with index.tsv")
    parser.add_argument("--uavs", type=int, help="keep the scenarios with this many UAVs")
    parser.add_argument("--build", default=os.path.join(REPO, "build"))
    parser.add_argument("--jobs", type=int, default=2, help="placements at a time (default 2)")
    parser.add_argument("--csv", help="also write the rows here")
    parser.add_argument("--oracle-cache", metavar="FILE",
                        help="oracle rewards kept between runs (created if missing)")
    args = parser.parse_args()
    sim = os.path.join(args.build, "bin", "rlpos-sim")
    try:
        cache = load_cache(args.oracle_cache)
    except OracleCacheError as e:
        fail(str(e))
    if not os.access(sim, os.X_OK):
        fail("%s not built" % sim)
    try:
        identity = binding_identity(args.build) if args.oracle_cache else ""
    except OracleCacheError as e:
        fail(str(e))
    rlpos = import_rlpos(args.build)

    scenarios = scenarios_of(args.scenarios, args.uavs)
    if not scenarios:
        fail("no scenario in %s with %s UAVs" % (args.scenarios, args.uavs))
    with open(os.path.join(args.policy, "scenario.json")) as f:
        cells = json.load(f).get("env", {}).get("coverage_map", 8)
    keys = {s: oracle_key(s, ORACLE_KIND, identity) for s in scenarios} if args.oracle_cache \
        else {}
    rows = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        rl = {s: pool.submit(placed, sim, args.policy, s) for s in scenarios}
        best = {s: pool.submit(oracle, rlpos, s) for s in scenarios
                if keys.get(s) not in cache}
        print("| scenario | rl | map's best | oracle | rl / oracle | map / oracle | rl s | oracle s |")
        print("|---|---|---|---|---|---|---|---|")
        for s in scenarios:
            reward, rl_s = rl[s].result()
            if s in best:
                top, oracle_s = best[s].result()
                if args.oracle_cache:
                    cache[keys[s]] = top
                    save_cache(args.oracle_cache, cache)
            else:
                top, oracle_s = cache[keys[s]], None
            coarse = map_best(rlpos, s, cells)
            ratio = reward / top if top > 0 else 1.0
            map_ratio = coarse / top if top > 0 else 1.0
            rows.append({"scenario": os.path.basename(s), "reward": reward, "map_best": coarse,
                         "oracle": top, "ratio": ratio, "map_ratio": map_ratio, "rl_s": rl_s,
                         "oracle_s": oracle_s})
            print("| %s | %.4f | %.4f | %.4f | %.3f | %.3f | %.2f | %s |" %
                  (os.path.basename(s), reward, coarse, top, ratio, map_ratio, rl_s,
                   "cached" if oracle_s is None else "%.2f" % oracle_s), flush=True)
    ratios = [r["ratio"] for r in rows]
    map_ratios = [r["map_ratio"] for r in rows]
    worst = min(rows, key=lambda r: r["ratio"])
    slowest = max(rows, key=lambda r: r["rl_s"])
    timed = [r["oracle_s"] for r in rows if r["oracle_s"] is not None]
    print()
    print("%d scenarios: median %.3f, P10 %.3f, >= 0.95 in %d (%.0f%%), under 0.8 in %d, "
          "worst %.3f (%s); seconds per placement: rl median %.2f, slowest %.2f (%s); "
          "oracle median %s" %
          (len(rows), statistics.median(ratios), percentile(ratios, 0.10),
           sum(r >= 0.95 for r in ratios), 100.0 * sum(r >= 0.95 for r in ratios) / len(ratios),
           sum(r < 0.8 for r in ratios), worst["ratio"], worst["scenario"],
           statistics.median(r["rl_s"] for r in rows), slowest["rl_s"], slowest["scenario"],
           "%.2f" % statistics.median(timed) if timed else "cached"))
    print("the map's best alone: median %.3f, P10 %.3f, >= 0.95 in %d, worst %.3f" %
          (statistics.median(map_ratios), percentile(map_ratios, 0.10),
           sum(r >= 0.95 for r in map_ratios), min(map_ratios)))
    if args.csv:
        write_csv(args.csv, rows)


if __name__ == "__main__":
    main()
