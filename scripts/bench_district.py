#!/usr/bin/env python3
"""A district of several hundred buildings against B and A: what a step and an eval cost.

Imports the whole shipped OpenStreetMap extract as a district (387 buildings) twice, with 4 and
with 20 UEs:

  rlpos-sim import --from osm data/osm/helsinki-central.osm.pbf
      --bbox 24.9353,60.1643,24.9533,60.1724 --ues N --seed 7 --out district-N.json

and measures, on it and on scenarios B (5 buildings, 4 UEs) and A (free space, 20 UEs):
  - the analytic env alone (seeded random actions, no agent) and with the DQN agent acting and
    learning: `rlpos-bench-env SCENARIO --agent-steps 1 --env-steps` (steps/s);
  - the batched env: rlpos.make_vec with --num-envs analytic envs, random actions (env steps/s);
  - one packet-level eval: `rlpos-sim eval` at the centroid positioner's position
    (`rlpos-sim position --positioner centroid`) for --duration simulated seconds, RngRun 1
    (wall seconds of the whole command).
Each figure is the median of --rounds; the rounds alternate the builds (--build, repeatable) so
that two builds are measured side by side under the same load. A build is a build folder, or a
copy of one's programs: DIR/bin (rlpos-bench-env, rlpos-sim), DIR/python (the rlpos package)
and, when it holds the shared libraries librlpos_*.so, DIR/lib (put first on LD_LIBRARY_PATH).
A third district row has 4 UEs and a UAV zone of B's size (100 x 100 m, 5-60 m up, about the
baseline), so that the env's memo of placements hits as often as on B. Then the ratios that judge
a district's cost, like for like: the district (4 UEs, either zone) against B and the district
(20 UEs) against A, per build. With two builds or more it also says whether every build
printed the same eval (the same numbers to the bit).

  build/bin/rlpos-python scripts/bench_district.py [--build build ...] [--rounds 3]
      [--env-steps 200000] [--agent-steps 3000] [--num-envs 8] [--vec-steps 200000]
      [--duration 2] [--only env,agent,vec,eval]
"""
import argparse
import glob
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

from bench_common import cpu_model

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
EXTRACT = os.path.join("data", "osm", "helsinki-central.osm.pbf")
BBOX = "24.9353,60.1643,24.9533,60.1724"
FIGURES = ("env", "agent", "vec", "eval")
TITLES = {"env": "env alone (steps/s)", "agent": "with the agent (steps/s)",
          "vec": "make_vec (env steps/s)", "eval": "packet eval (s)"}


def environment_of(build):
    """The environment a build's programs run in: its lib/ first when it holds the libraries."""
    env = dict(os.environ)
    lib = os.path.join(build, "lib")
    if glob.glob(os.path.join(lib, "librlpos_*.so*")):
        env["LD_LIBRARY_PATH"] = lib + (":" + env["LD_LIBRARY_PATH"]
                                        if env.get("LD_LIBRARY_PATH") else "")
    env["PYTHONPATH"] = os.path.join(build, "python") + (
        ":" + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    return env


def run(command, env, **kwargs):
    done = subprocess.run(command, env=env, capture_output=True, text=True, **kwargs)
    if done.returncode != 0:
        sys.exit("bench_district.py: %s: exit %d: %s" %
                 (" ".join(command), done.returncode, done.stderr.strip()[-500:]))
    return done.stdout


def bench_env(build, scenario, args):
    """(env alone, with the agent) steps/s from one rlpos-bench-env run."""
    out = run([os.path.join(build, "bin", "rlpos-bench-env"), scenario, str(args.agent_steps),
               "1", str(args.env_steps)], environment_of(build))
    agent = re.search(r"analytic\s+([0-9.]+) steps/s \|", out)
    alone = re.search(r"env alone \(random actions, no agent\)\s+([0-9.]+) steps/s", out)
    if not agent or not alone:
        sys.exit("bench_district.py: unexpected rlpos-bench-env output:\n" + out)
    return float(alone.group(1)), float(agent.group(1))


def bench_vec(build, scenario, args):
    """make_vec's env steps/s, measured in a child with the build's rlpos."""
    out = run([sys.executable, os.path.abspath(__file__), "--vec-of", scenario, "--num-envs",
               str(args.num_envs), "--vec-steps", str(args.vec_steps)], environment_of(build))
    return float(out)


def measure_vec_here(scenario, num_envs, steps):
    import numpy as np
    import rlpos
    env = rlpos.make_vec(scenario, num_envs=num_envs, seed=1)
    calls = max(1, steps // num_envs)
    actions = np.random.default_rng(1).integers(0, env.action_space.nvec[0],
                                                size=(calls, num_envs), dtype=np.int64)
    env.reset(seed=1)
    env.step(actions[0])  # threads started, buffers allocated
    started = time.perf_counter()
    for a in actions:
        env.step(a)
    seconds = time.perf_counter() - started
    env.close()
    return calls * num_envs / seconds


def bench_eval(build, scenario, args):
    """(wall seconds, eval JSON) of one packet-level eval at the centroid's position."""
    env = environment_of(build)
    sim = os.path.join(build, "bin", "rlpos-sim")
    placed = json.loads(run([sim, "position", "--scenario", scenario, "--positioner", "centroid",
                             "--json"], env))
    where = ",".join("%r" % v for v in placed["position"])
    started = time.monotonic()
    out = run([sim, "eval", "--scenario", scenario, "--position", where, "--duration",
               str(args.duration), "--RngRun", "1", "--json", "--no-progress"], env)
    return time.monotonic() - started, out


def import_district(build, folder, ues):
    path = os.path.join(folder, "district-%d.json" % ues)
    run([os.path.join(build, "bin", "rlpos-sim"), "import", "--from", "osm",
         os.path.join(REPO, EXTRACT), "--bbox", BBOX, "--ues", str(ues), "--seed", "7", "--out",
         path], environment_of(build))
    return path


def with_small_zone(path, folder):
    """The district with B's zone size (100 x 100 m, 5-60 m up) about its UAV's baseline: as few
    placements to visit as B, so that the env's memo of placements hits as often as on B."""
    with open(path) as f:
        s = json.load(f)
    x, y, _ = s["uav"]["position"]
    s["uav"]["zone"] = {"x": [x - 50, x + 50], "y": [y - 50, y + 50], "z": [5, 60]}
    out = os.path.join(folder, "district-4-zone100.json")
    with open(out, "w") as f:
        json.dump(s, f)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", action="append",
                        help="a build folder or a copy of its programs (repeatable; default build)")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--env-steps", type=int, default=200000)
    parser.add_argument("--agent-steps", type=int, default=3000)
    parser.add_argument("--num-envs", type=int, default=8)
    parser.add_argument("--vec-steps", type=int, default=200000)
    parser.add_argument("--duration", type=float, default=2.0,
                        help="simulated seconds of the packet-level eval")
    parser.add_argument("--only", default=",".join(FIGURES),
                        help="figures to measure, among %s" % ",".join(FIGURES))
    parser.add_argument("--vec-of", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.vec_of:
        print(measure_vec_here(args.vec_of, args.num_envs, args.vec_steps))
        return 0
    figures = [f for f in args.only.split(",") if f]
    if not figures or any(f not in FIGURES for f in figures) or args.rounds < 1:
        parser.error("--only: expected some of %s; --rounds at least 1" % ",".join(FIGURES))
    builds = args.build or [os.path.join(REPO, "build")]

    with tempfile.TemporaryDirectory(prefix="bench_district.") as folder:
        district4 = import_district(builds[0], folder, 4)
        scenarios = [("B", os.path.join(REPO, "campaigns", "scenarios", "b.json")),
                     ("district, 4 UEs", district4),
                     ("district, 4 UEs, B's zone size", with_small_zone(district4, folder)),
                     ("A", os.path.join(REPO, "campaigns", "scenarios", "a.json")),
                     ("district, 20 UEs", import_district(builds[0], folder, 20))]
        results = {}  # (scenario, build, figure) -> [values]
        evals = {}    # (scenario, build) -> eval JSON
        for _ in range(args.rounds):
            for name, path in scenarios:
                for build in builds:
                    def add(figure, value):
                        results.setdefault((name, build, figure), []).append(value)
                    if "env" in figures or "agent" in figures:
                        alone, agent = bench_env(build, path, args)
                        add("env", alone)
                        add("agent", agent)
                    if "vec" in figures:
                        add("vec", bench_vec(build, path, args))
                    if "eval" in figures:
                        seconds, out = bench_eval(build, path, args)
                        add("eval", seconds)
                        evals[(name, build)] = out

    print("%d cores, %s; %d rounds, medians; builds alternated" %
          (os.cpu_count(), cpu_model(), args.rounds))
    print()
    header = ["scenario"] + ["%s, %s" % (TITLES[f], b) for f in figures for b in builds]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    median = {k: statistics.median(v) for k, v in results.items()}
    for name, _ in scenarios:
        cells = [name]
        for f in figures:
            for b in builds:
                value = median[(name, b, f)]
                cells.append("%.2f" % value if f == "eval" else "{:,.0f}".format(value))
        print("| " + " | ".join(cells) + " |")
    print()
    for f in figures:
        for b in builds:
            # A cost: steps/s inverted; the eval's seconds as they are.
            def cost(name):
                v = median[(name, b, f)]
                return v if f == "eval" else 1.0 / v
            print("%s, %s: cost of the district over B %.2fx (B's zone size: %.2fx), over A "
                  "%.2fx" % (TITLES[f], b, cost("district, 4 UEs") / cost("B"),
                             cost("district, 4 UEs, B's zone size") / cost("B"),
                             cost("district, 20 UEs") / cost("A")))
    if len(builds) > 1 and "eval" in figures:
        same = all(evals[(n, b)] == evals[(n, builds[0])] for n, _ in scenarios for b in builds)
        print("every build printed the same evals: %s" % ("yes" if same else "NO"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
