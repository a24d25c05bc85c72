#!/usr/bin/env python3
"""UEs that walk, UAVs that follow: held placements against tracking ones on held-out scenarios.

Generates held-out one-UAV scenarios whose UEs move (rlpos-sim generate --mobility; the held-out
set's seeds 91000 + 100 * style + i, so their buildings and UEs are those of
scripts/generate_scenario_set.sh --set heldout, which no policy trains on), i = 0 .. --per-style
- 1 with the mobility models taken in turn. In each, one run of --duration s (RngRun --run) with
`rlpos-sim track`, decisions every --interval s, for the positioners: oracle (held at its
placement for t = 0), oracle-track, centroid-track, and rl with --policy (a policy for any
scenario, flown again at every decision). Prints one row per scenario (mean reward of each, rl
over oracle-track, seconds per run) and the summary the mobility acceptance reads: the share of
scenarios where oracle-track beats the held oracle, the share where rl reaches 90 % of
oracle-track, the medians of rl and centroid-track, and the worst cases.

  scripts/bench_tracking.py [--policy policies/generalist-1uav] [--per-style 6]
                            [--duration 120] [--interval 1] [--run 1] [--jobs 2]
                            [--build DIR] [--out DIR] [--csv FILE]
"""
import argparse
import concurrent.futures
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from bench_common import add_track_run_arguments, write_csv

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
STYLES = ("urban", "campus", "suburb", "open")
MODELS = ("random_waypoint", "gauss_markov", "crowd")
POSITIONERS = ("oracle", "oracle-track", "centroid-track", "rl")


def fail(message):
    print("bench_tracking: %s" % message, file=sys.stderr)
    sys.exit(2)


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail("%s: %s" % (" ".join(command[1:4]), done.stderr.strip()))
    return done.stdout


def scenarios(sim, folder, per_style):
    """(file, style, model) of each generated scenario."""
    out = []
    for s, style in enumerate(STYLES):
        for i in range(per_style):
            model = MODELS[i % len(MODELS)]
            seed = 91000 + 100 * s + i
            path = os.path.join(folder, "%s-%s-s%d.json" % (style, model, seed))
            run([sim, "generate", "--seed", str(seed), "--style", style, "--uavs", "1",
                 "--mobility", model, "--out", path])
            out.append((path, style, model))
    return out


def track(sim, scenario, positioner, args):
    command = [sim, "track", "--scenario", scenario, "--positioner", positioner,
               "--duration", str(args.duration), "--RngRun", str(args.run), "--json",
               "--set", "env.decision_interval=%s" % args.interval]
    if positioner == "rl":
        command += ["--policy", args.policy]
    started = time.monotonic()
    result = json.loads(run(command))
    return result["mean_reward"], time.monotonic() - started


def share(flags):
    return sum(flags), len(flags), 100.0 * sum(flags) / len(flags)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--policy", default=os.path.join(REPO, "policies", "generalist-1uav"))
    add_track_run_arguments(parser, 6, 120.0, "RngRun: the trajectories (default 1)")
    parser.add_argument("--jobs", type=int, default=2, help="runs at a time (default 2)")
    parser.add_argument("--build", default=os.path.join(REPO, "build"))
    parser.add_argument("--out", help="keep the generated scenarios here (default: a temp dir)")
    parser.add_argument("--csv", help="also write the rows here")
    args = parser.parse_args()
    if args.per_style < 1 or args.jobs < 1 or args.duration <= 0 or args.interval <= 0:
        fail("--per-style and --jobs must be at least 1, --duration and --interval positive")
    sim = os.path.join(args.build, "bin", "rlpos-sim")
    if not os.access(sim, os.X_OK):
        fail("%s not built" % sim)
    if not os.path.isfile(os.path.join(args.policy, "result.json")):
        fail("--policy: %s holds no policy (result.json)" % args.policy)

    with tempfile.TemporaryDirectory(prefix="rlpos-tracking-") as temp:
        folder = args.out or temp
        os.makedirs(folder, exist_ok=True)
        cases = scenarios(sim, folder, args.per_style)
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            futures = {(c[0], p): pool.submit(track, sim, c[0], p, args)
                       for c in cases for p in POSITIONERS}
            rows = []
            print("| scenario | oracle (held) | oracle-track | centroid-track | rl | "
                  "rl / oracle-track | oracle-track s | rl s |")
            print("|---|---|---|---|---|---|---|---|")
            for path, style, model in cases:
                got = {p: futures[(path, p)].result() for p in POSITIONERS}
                row = {"scenario": os.path.basename(path), "style": style, "model": model}
                for p in POSITIONERS:
                    row[p] = got[p][0]
                    row[p + "_s"] = got[p][1]
                row["rl_ratio"] = row["rl"] / row["oracle-track"] if row["oracle-track"] > 0 else 1.0
                rows.append(row)
                print("| %s | %.4f | %.4f | %.4f | %.4f | %.3f | %.1f | %.1f |" % (
                    row["scenario"], row["oracle"], row["oracle-track"], row["centroid-track"],
                    row["rl"], row["rl_ratio"], row["oracle-track_s"], row["rl_s"]), flush=True)

    beats = share([r["oracle-track"] > r["oracle"] for r in rows])
    near = share([r["rl_ratio"] >= 0.9 for r in rows])
    worst = sorted(rows, key=lambda r: r["rl_ratio"])[:3]
    print()
    print("%d scenarios, %g s each, decisions every %g s, RngRun %d" %
          (len(rows), args.duration, args.interval, args.run))
    print("oracle-track beats the held oracle in %d of %d (%.0f %%)" % beats)
    print("rl reaches 0.9 of oracle-track in %d of %d (%.0f %%); rl / oracle-track median %.3f, "
          "worst %s" % (near + (statistics.median(r["rl_ratio"] for r in rows),
                               ", ".join("%.3f (%s)" % (r["rl_ratio"], r["scenario"])
                                         for r in worst))))
    print("median mean reward: rl %.4f, centroid-track %.4f, oracle-track %.4f, oracle (held) %.4f"
          % tuple(statistics.median(r[p] for r in rows)
                  for p in ("rl", "centroid-track", "oracle-track", "oracle")))
    print("median seconds per run: rl %.1f, oracle-track %.1f" %
          (statistics.median(r["rl_s"] for r in rows),
           statistics.median(r["oracle-track_s"] for r in rows)))
    if args.csv:
        write_csv(args.csv, rows)


if __name__ == "__main__":
    main()
