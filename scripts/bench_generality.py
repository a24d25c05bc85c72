#!/usr/bin/env python3
"""The generality benchmark: how close rl comes to the oracle on a set of scenarios.

Writes a campaign of every scenario JSON of a folder (positioners oracle and rl; each algorithm
trains its own policies with train seeds --seeds, at analytic fidelity), runs it with
`rlpos-campaign run` (an embedded coordinator and --workers workers on loopback), then prints
the optimality table: per algorithm and number of UAVs, rl's reward over the oracle's (median,
P10, worst, share of runs >= 0.95, median seconds per placement). The report folder has every
run (optimality.csv) and the ratio's CDF (optimality_cdf.png).

Zero-shot mode: each --policy DIR (a policy for any scenario, `rlpos-sim train --generated`)
places UAVs in every scenario with no training there, beside the per-scenario training (or
instead of it, with --algorithms none) and the centroid positioner, each against the oracle, with
the seconds per placement. Scenarios with a UAV count a policy was not trained for are left out
(and said so).

  scripts/bench_generality.py [--scenarios DIR] [--algorithms dqn,ppo,sac|none] [--seeds 1-3]
                              [--policy DIR ...] [--workers 2] [--build DIR] [--db FILE]
                              [--campaign FILE] [--episodes N] [--set PATH=VALUE ...]
                              [--name NAME] [--tag TAG] [--dry-run]

Running it again resumes the same campaign (its id is a hash of its content). Exit status:
rlpos-campaign run's (0: every job succeeded), 2 for bad arguments.
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import time

from plot_campaign import replace_atomically

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
ALGORITHMS = ("dqn", "ppo", "sac")


def fail(message):
    print(f"bench_generality: {message}", file=sys.stderr)
    sys.exit(2)


def seeds_of(text):
    """"1-3" or "1,2,5" -> [1, 2, 3] / [1, 2, 5]."""
    try:
        if "-" in text:
            first, last = (int(x) for x in text.split("-", 1))
            seeds = list(range(first, last + 1))
        else:
            seeds = [int(x) for x in text.split(",")]
    except ValueError:
        fail(f"--seeds: expected FIRST-LAST or a comma-separated list, got \"{text}\"")
    if not seeds or min(seeds) < 0 or len(set(seeds)) != len(seeds):
        fail(f"--seeds: expected distinct non-negative seeds, got \"{text}\"")
    return seeds


def algorithms_of(text):
    if text == "none":
        return []
    chosen = [a for a in text.split(",") if a]
    for a in chosen:
        if a not in ALGORITHMS:
            fail(f"--algorithms: unknown algorithm \"{a}\" (one of: {', '.join(ALGORITHMS)})")
    if not chosen:
        fail("--algorithms: none given")
    return chosen


def scenario_files(folder):
    if not os.path.isdir(folder):
        fail(f"--scenarios: {folder} is not a folder")
    files = sorted(glob.glob(os.path.join(folder, "*.json")))
    if not files:
        fail(f"--scenarios: {folder} holds no *.json scenario")
    return files


def scenario_document(path):
    try:
        with open(path) as f:
            document = json.load(f)
    except (OSError, ValueError) as error:
        fail(f"{path}: {error}")
    return document if isinstance(document, dict) else {}


def uav_count(document):
    """A scenario's UAVs: "uavs" (a list) or the one "uav"."""
    uavs = document.get("uavs")
    return len(uavs) if isinstance(uavs, list) else 1


def policy_uavs(folder):
    """(min, max) UAVs a policy for any scenario was trained for, from its result.json."""
    path = os.path.join(folder, "result.json")
    try:
        with open(path) as f:
            result = json.load(f)
    except (OSError, ValueError) as error:
        fail(f"--policy: {path}: {error}")
    if not isinstance(result, dict) or result.get("general") is not True:
        fail(f"--policy: {folder} is not a policy for any scenario (its result.json has no "
             "\"general\": true; train one with rlpos-sim train --generated)")
    uavs = result.get("training", {}).get("uavs")
    if (not isinstance(uavs, list) or len(uavs) != 2 or
            not all(isinstance(u, int) and u >= 1 for u in uavs) or uavs[0] > uavs[1]):
        fail(f"--policy: {path}: /training/uavs: expected [min, max] UAV counts")
    return uavs[0], uavs[1]


def fitting(files, policies):
    """The scenarios every policy was trained for; says which were left out."""
    kept = []
    for f in files:
        uavs = uav_count(scenario_document(f))
        misfits = [p for p, (low, high) in policies.items() if not low <= uavs <= high]
        if misfits:
            low, high = policies[misfits[0]]
            places = f"{low}" if low == high else f"{low}-{high}"
            print(f"bench_generality: left out {os.path.basename(f)} ({uavs} UAV(s)): "
                  f"{misfits[0]} places {places} UAV(s)", file=sys.stderr)
        else:
            kept.append(f)
    if not kept:
        fail("--policy: no scenario of --scenarios has a UAV count every policy was trained for")
    return kept


def campaign_of(args, files, campaign_file):
    """The campaign JSON; scenario paths relative to the campaign's folder, as a campaign wants
    them (an absolute path would make the campaign id depend on the checkout's place)."""
    folder = os.path.dirname(os.path.abspath(campaign_file))
    scenarios, names = [], set()
    for f in files:
        path = os.path.relpath(os.path.abspath(f), folder)
        overrides = list(args.set)
        name = scenario_document(f).get("name", "")
        if name in names:  # a campaign's scenario names must differ: the file's stem instead
            name = re.sub(r"[^A-Za-z0-9._@+-]", "_", os.path.splitext(os.path.basename(f))[0])
            overrides.append("name=" + name)
        names.add(name)
        scenarios.append({"file": path, "set": overrides} if overrides else path)
    algorithms = algorithms_of(args.algorithms)
    positioners = ["oracle"]
    if algorithms:
        positioners.append("rl")
    if args.policy:  # zero-shot: the policies, and centroid as the placement with no search
        positioners.append("centroid")
        positioners += [{"rl": {"policy": os.path.relpath(os.path.abspath(p), folder)}}
                        for p in args.policy]
    # The rewards come from the analytic model; the packet-level evals only need to exist.
    campaign = {"name": args.name, "scenarios": scenarios, "rng_runs": [1, 1],
                "positioners": positioners, "eval": {"duration": 1, "warmup": 0.5},
                "retries": 1, "job_timeout_s": 3600}
    if algorithms:
        campaign["train"] = {"seeds": seeds_of(args.seeds), "fidelity": "analytic",
                             "algorithms": algorithms}
        if args.episodes is not None:
            campaign["train"]["episodes"] = args.episodes
    return campaign


def write_atomically(path, text):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    replace_atomically(path, lambda f: f.write(text), "w")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenarios", default=os.path.join(REPO, "campaigns", "scenarios"),
                        help="folder of scenario JSON files (default: the shipped ones)")
    parser.add_argument("--algorithms", default=",".join(ALGORITHMS),
                        help="default dqn,ppo,sac; none: no per-scenario training (with --policy)")
    parser.add_argument("--seeds", default="1-3", help="train seeds, 1-3 or 1,2,5 (default 1-3)")
    parser.add_argument("--policy", action="append", default=[], metavar="DIR",
                        help="zero-shot: a policy for any scenario placing with no training, "
                        "beside centroid (repeatable)")
    parser.add_argument("--workers", type=int, default=2, help="workers, one job each (default 2)")
    parser.add_argument("--build", default=os.path.join(REPO, "build"), help="build folder")
    parser.add_argument("--db", help="results database (default: rlpos-campaign's)")
    parser.add_argument("--campaign", help="where the campaign JSON is written (default: "
                        "generality.json beside the database)")
    parser.add_argument("--episodes", type=int, help="train episodes (default: the scenario's)")
    parser.add_argument("--set", action="append", default=[], metavar="PATH=VALUE",
                        help="an override of every scenario (repeatable)")
    parser.add_argument("--name", default="generality", help="campaign name")
    parser.add_argument("--tag", help="DDS discovery tag (default: a random one)")
    parser.add_argument("--dry-run", action="store_true", help="write the campaign, run nothing")
    args = parser.parse_args()
    if args.workers < 1:
        fail("--workers: must be at least 1")
    if args.episodes is not None and args.episodes < 1:
        fail("--episodes: must be at least 1")
    if not algorithms_of(args.algorithms) and not args.policy:
        fail("--algorithms none: nothing to compare without a --policy")

    campaign_bin = os.path.join(args.build, "bin", "rlpos-campaign")
    if not os.access(campaign_bin, os.X_OK):
        fail(f"{campaign_bin} not found: build first (or pass --build)")
    db_dir = os.path.dirname(os.path.abspath(args.db)) if args.db else os.path.join(REPO, "results")
    campaign_file = args.campaign or os.path.join(db_dir, "generality.json")
    files = scenario_files(args.scenarios)
    if args.policy:
        files = fitting(files, {p: policy_uavs(p) for p in args.policy})
    campaign = campaign_of(args, files, campaign_file)
    write_atomically(campaign_file, json.dumps(campaign, indent=2) + "\n")
    db = ["--db", args.db] if args.db else []

    run = [campaign_bin, "run", campaign_file] + db
    if args.dry_run:
        return subprocess.run(run + ["--dry-run"]).returncode
    run += ["--workers", str(args.workers), "--no-progress"]
    if args.tag:
        run += ["--tag", args.tag]
    started = time.monotonic()
    done = subprocess.run(run, stdout=subprocess.PIPE, text=True)
    wall = time.monotonic() - started
    ids = [line.split()[1] for line in done.stdout.splitlines() if line.startswith("campaign ")]
    if not ids:
        sys.stdout.write(done.stdout)
        print(f"bench_generality: rlpos-campaign run printed no campaign id (exit {done.returncode})",
              file=sys.stderr)
        return done.returncode or 1
    reports = [line for line in done.stdout.splitlines() if line.startswith("report: ")]
    table = subprocess.run([campaign_bin, "results", ids[-1], "--optimality"] + db,
                           stdout=subprocess.PIPE, text=True)
    train = campaign.get("train", {"algorithms": ["none"], "seeds": []})
    print(f"generality benchmark: {len(campaign['scenarios'])} scenarios, algorithms "
          f"{','.join(train['algorithms'])}, seeds "
          f"{','.join(str(s) for s in train['seeds']) or '-'}"
          f"{''.join(', policy ' + p for p in args.policy)}, {args.workers} workers: "
          f"{wall:.0f} s wall")
    print(f"campaign {ids[-1]} ({campaign_file})")
    if reports:
        print(reports[-1] + " (optimality.csv: every run; optimality_cdf.png)")
    print("optimality (each placement's reward / the oracle's; placement s: the median seconds "
          "of the job that found it):")
    sys.stdout.write(table.stdout)
    return done.returncode or table.returncode


if __name__ == "__main__":
    sys.exit(main())
