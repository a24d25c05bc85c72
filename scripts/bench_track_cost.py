#!/usr/bin/env python3
"""What tracking costs at packet level: a run whose UAVs fly against the same run held static.

Generates held-out one-UAV scenarios whose UEs move (rlpos-sim generate --mobility; the seeds of
scripts/bench_tracking.py: 91000 + 100 * style + i, i = 0 .. --per-style - 1, the mobility models
in turn). In each, `rlpos-sim track --fidelity packet` for --duration s (RngRun --run, decisions
every --interval s) with each held positioner and its tracking twin, the two side by side on the
two cores: centroid against centroid-track, oracle against oracle-track. Then the held centroid
again beside `rlpos-sim eval` at its placement: the same packets, without the decision
intervals. Prints per scenario and pair the CPU seconds (user + system of the process) and the
mean throughput of each (a run that serves more carries more packets), and the ratios: track
over held, and held over eval.

  scripts/bench_track_cost.py [--per-style 1] [--duration 60] [--interval 1] [--run 1]
                              [--build DIR]
"""
import argparse
import concurrent.futures
import json
import os
import statistics
import subprocess
import sys
import tempfile

from bench_common import add_track_run_arguments

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
STYLES = ("urban", "campus", "suburb", "open")
MODELS = ("random_waypoint", "gauss_markov", "crowd")
PAIRS = (("centroid", "centroid-track"), ("oracle", "oracle-track"))


def fail(message):
    print("bench_track_cost: %s" % message, file=sys.stderr)
    sys.exit(2)


def timed(command):
    """(stdout, CPU seconds of the process: user + system)."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        process = subprocess.Popen(command, stdout=out, stderr=err)
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        if process.returncode != 0:
            how = ("killed by signal %d" % -process.returncode if process.returncode < 0
                   else "exit code %d" % process.returncode)
            fail("%s (%s): %s" % (" ".join(command[1:]), how, err.read().decode().strip()))
        return out.read().decode(), usage.ru_utime + usage.ru_stime


def track(sim, scenario, positioner, args):
    stdout, cpu = timed([sim, "track", "--scenario", scenario, "--positioner", positioner,
                         "--duration", str(args.duration), "--RngRun", str(args.run),
                         "--fidelity", "packet", "--json",
                         "--set", "env.decision_interval=%s" % args.interval])
    result = json.loads(stdout)
    return {"cpu": cpu, "throughput": result["mean_throughput_mbps"],
            "reward": result["mean_reward"],
            "position": result["series"][0]["positions"][0]}


def evaluate(sim, scenario, position, args):
    stdout, cpu = timed([sim, "eval", "--scenario", scenario,
                         "--position", ",".join(repr(v) for v in position),
                         "--duration", str(args.duration), "--RngRun", str(args.run), "--json"])
    return {"cpu": cpu, "throughput": json.loads(stdout)["aggregate_throughput_mbps"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_track_run_arguments(parser, 1, 60.0, "RngRun (default 1)")
    parser.add_argument("--build", default=os.path.join(REPO, "build"))
    args = parser.parse_args()
    if args.per_style < 1 or args.duration <= 0 or args.interval <= 0:
        fail("--per-style must be at least 1, --duration and --interval positive")
    sim = os.path.join(args.build, "bin", "rlpos-sim")
    if not os.access(sim, os.X_OK):
        fail("%s not built" % sim)

    ratios = {held: [] for held, _ in PAIRS}
    eval_ratios = []
    print("| scenario | held | CPU s | Mbit/s | tracking | CPU s | Mbit/s | track / held |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="rlpos-track-cost-") as folder, \
            concurrent.futures.ThreadPoolExecutor(2) as pool:
        for s, style in enumerate(STYLES):
            for i in range(args.per_style):
                model = MODELS[i % len(MODELS)]
                seed = 91000 + 100 * s + i
                name = "%s-%s-s%d" % (style, model, seed)
                path = os.path.join(folder, name + ".json")
                timed([sim, "generate", "--seed", str(seed), "--style", style, "--uavs", "1",
                       "--mobility", model, "--out", path])
                for held, tracking in PAIRS:
                    a = pool.submit(track, sim, path, held, args)
                    b = pool.submit(track, sim, path, tracking, args)
                    h, t = a.result(), b.result()
                    ratios[held].append(t["cpu"] / h["cpu"])
                    print("| %s | %s | %.1f | %.1f | %s | %.1f | %.1f | %.3f |" % (
                        name, held, h["cpu"], h["throughput"], tracking, t["cpu"],
                        t["throughput"], t["cpu"] / h["cpu"]), flush=True)
                    if held == "centroid":
                        # Side by side too: a run alone is not slowed by its neighbour.
                        a = pool.submit(track, sim, path, held, args)
                        b = pool.submit(evaluate, sim, path, h["position"], args)
                        h2, e = a.result(), b.result()
                        eval_ratios.append(h2["cpu"] / e["cpu"])
                        print("| %s | %s (again) | %.1f | %.1f | eval at its placement | %.1f | "
                              "%.1f | held / eval %.3f |" % (
                                  name, held, h2["cpu"], h2["throughput"], e["cpu"],
                                  e["throughput"], h2["cpu"] / e["cpu"]), flush=True)
    print()
    print("%g s runs at packet level, decisions every %g s, RngRun %d" %
          (args.duration, args.interval, args.run))
    for held, tracking in PAIRS:
        r = ratios[held]
        print("%s / %s CPU: median %.3f, worst %.3f over %d scenarios" %
              (tracking, held, statistics.median(r), max(r), len(r)))
    print("held centroid (track) / eval CPU: median %.3f, worst %.3f" %
          (statistics.median(eval_ratios), max(eval_ratios)))


if __name__ == "__main__":
    main()
