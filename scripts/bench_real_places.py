#!/usr/bin/env python3
"""Real places, zero-shot: the shipped policies for any scenario on OpenStreetMap crops nobody tuned for.

Cuts --crops seeded venues out of a real OpenStreetMap extract (default
data/osm/helsinki-central.osm.pbf) and asks how the shipped policies for any scenario place UAVs
there, against the oracle and the centroid positioner. Crop i takes, from one random.Random(--seed)
stream drawn crop after crop (so the first crops are the same whatever --crops is), a centre
inside the extract's data box such that the whole --size venue lies inside it, a number of UE
groups (0-2), a number of UAVs for the several-UAV set (--many-uavs, default 2-4) and the seed of
the UE draw. Each set makes the crop with

  rlpos-sim import --from osm FILE --center LAT,LON --size WxD --ues N --ue-groups K --uavs U
      --seed S --out crop.json

into a temporary folder (the one-UAV set with --uavs 1, the several-UAV set with the crop's
count; both sets share the centre, the groups and the seed). A crop the importer refuses is
reported with its error and skipped, not hidden. On each crop
`rlpos-sim position --scenario crop.json --positioner P --json` runs for P = rl (--policy
policies/generalist-1uav for one UAV, policies/generalist-multi for several), oracle (one UAV:
the exhaustive grid search; several: its coordinate descent from 8 starts) and centroid (for
several UAVs the demand-weighted k-means of the UEs; rlpos-sim has no other k-means positioner).
Each one's `reward` (the analytic reward) is recorded with the wall time of its whole command
(process start, scenario load, policy load, search), measured with time.monotonic.

Prints per set a row per crop (centre, buildings, UAVs, the reward of each positioner, rl's
ratio to the oracle, the seconds of each) and a summary: the share of crops where rl reaches
0.95 of the oracle's reward, the worst ratio, the median and the largest seconds of an rl
placement; then the command that reproduces the run. The oracle takes tens of seconds per crop
on 2 cores (more with several UAVs): try --crops 2 first.

  scripts/bench_real_places.py [--crops 24] [--seed 1] [--size 300x300] [--ues 20]
      [--file data/osm/helsinki-central.osm.pbf] [--box MINLON,MINLAT,MAXLON,MAXLAT]
      [--sets one,several] [--many-uavs 2-4] [--jobs 1] [--build DIR]

--box is the data box of --file (default: the shipped extract's, lon 24.9352-24.9534,
lat 60.1642-60.1725, from data/osm/README.md); another --file needs its own. --jobs J makes J
crops at a time: the seconds then include the other crops' competition for the cores.

Exit status: 0; 1 if a positioner failed on some crop (reported) or no crop could be placed; 2
for bad options.
"""
import argparse
import concurrent.futures
import json
import math
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
DEFAULT_FILE = os.path.join("data", "osm", "helsinki-central.osm.pbf")
# The data box of the shipped extract (data/osm/README.md; osmium's --set-bounds box).
DEFAULT_BOX = (24.9352, 60.1642, 24.9534, 60.1725)
SETS = {
    # set: (title, policy folder under policies/)
    "one": ("one UAV", "generalist-1uav"),
    "several": ("several UAVs", "generalist-multi"),
}
POSITIONERS = ("rl", "oracle", "centroid")
TARGET = 0.95
# WGS84, for the degrees a venue's metres span.
WGS84_A = 6378137.0
WGS84_E2 = 6.69437999014e-3
# Metres kept between the venue and the data box's edge, beyond the importer's own metre.
EDGE_MARGIN_M = 1.0


def fail(message):
    print("bench_real_places: %s" % message, file=sys.stderr)
    sys.exit(2)


class Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2
        fail(message)


def size_of(text):
    """"300x300" or "300" -> (300.0, 300.0) metres, east-west by north-south."""
    parts = text.lower().split("x")
    try:
        sides = [float(p) for p in parts]
    except ValueError:
        fail("--size: expected WxD in metres (300x300) or one number, got \"%s\"" % text)
    if len(sides) == 1:
        sides *= 2
    if len(sides) != 2 or not all(math.isfinite(s) and 10 <= s <= 2000 for s in sides):
        fail("--size: expected WxD with sides from 10 to 2000 m, got \"%s\"" % text)
    return sides[0], sides[1]


def box_of(text):
    try:
        box = tuple(float(v) for v in text.split(","))
    except ValueError:
        box = ()
    if (len(box) != 4 or not all(math.isfinite(v) for v in box) or
            not (-180 <= box[0] < box[2] <= 180 and -90 < box[1] < box[3] < 90)):
        fail("--box: expected MINLON,MINLAT,MAXLON,MAXLAT in degrees, got \"%s\"" % text)
    return box


def range_of(text, option):
    """"2-4" or "3" -> (2, 4) / (3, 3)."""
    try:
        low, _, high = text.partition("-")
        low, high = int(low), int(high or low)
    except ValueError:
        fail("%s: expected MIN-MAX or one number, got \"%s\"" % (option, text))
    if not 2 <= low <= high:
        fail("%s: expected 2 <= MIN <= MAX, got \"%s\"" % (option, text))
    return low, high


def sets_of(text):
    chosen = [s for s in text.split(",") if s]
    for s in chosen:
        if s not in SETS:
            fail("--sets: unknown set \"%s\" (one of: %s)" % (s, ", ".join(SETS)))
    if not chosen or len(set(chosen)) != len(chosen):
        fail("--sets: expected distinct sets among %s, got \"%s\"" % (",".join(SETS), text))
    return chosen


def policy_uavs(folder):
    """(min, max) UAVs a policy for any scenario was trained for (its result.json)."""
    try:
        with open(os.path.join(folder, "result.json")) as f:
            uavs = json.load(f).get("training", {}).get("uavs")
        return int(uavs[0]), int(uavs[1])
    except (OSError, ValueError, TypeError, IndexError, AttributeError) as error:
        fail("%s: not a policy for any scenario (%s)" % (folder, error))


def half_span_degrees(box, size):
    """Half the venue's east-west and north-south extent in degrees of longitude and latitude,
    at the box's latitude farthest from the equator (where a metre spans the most longitude)."""
    lat = math.radians(max(abs(box[1]), abs(box[3])))
    lat_low = 0.0 if box[1] <= 0 <= box[3] else math.radians(min(abs(box[1]), abs(box[3])))
    w = 1.0 - WGS84_E2 * math.sin(lat) ** 2
    prime = WGS84_A / math.sqrt(w)  # prime vertical radius of curvature
    meridian = WGS84_A * (1 - WGS84_E2) / (1.0 - WGS84_E2 * math.sin(lat_low) ** 2) ** 1.5
    east = math.degrees((size[0] / 2 + EDGE_MARGIN_M) / (prime * math.cos(lat)))
    north = math.degrees((size[1] / 2 + EDGE_MARGIN_M) / meridian)
    return east, north


def draw_crops(args, many):
    """Crop i: its centre, UE groups, UAVs of the several-UAV set and UE seed, drawn in order."""
    half_lon, half_lat = half_span_degrees(args.box, args.size)
    lon_range = (args.box[0] + half_lon, args.box[2] - half_lon)
    lat_range = (args.box[1] + half_lat, args.box[3] - half_lat)
    if lon_range[0] > lon_range[1] or lat_range[0] > lat_range[1]:
        fail("--size: a %gx%g m venue does not fit in the data box %s" %
             (args.size[0], args.size[1], ",".join("%g" % v for v in args.box)))
    rng = random.Random(args.seed)
    crops = []
    for i in range(args.crops):
        lat = round(rng.uniform(*lat_range), 6)
        lon = round(rng.uniform(*lon_range), 6)
        # Rounding to 1e-6 degrees (< 0.1 m) may step past the range's end: clamp back.
        lat = min(max(lat, math.ceil(lat_range[0] * 1e6) / 1e6), math.floor(lat_range[1] * 1e6) / 1e6)
        lon = min(max(lon, math.ceil(lon_range[0] * 1e6) / 1e6), math.floor(lon_range[1] * 1e6) / 1e6)
        crops.append({"index": i + 1, "lat": lat, "lon": lon, "groups": rng.randint(0, 2),
                      "many": rng.randint(*many), "ue_seed": rng.randrange(1_000_000)})
    return crops


def first_error(stderr):
    lines = [l for l in stderr.strip().splitlines() if l.strip()]
    errors = [l for l in lines if "warning:" not in l]
    return (errors or lines or ["(no message)"])[-1]


def run_crop(args, sim, crop, set_name, uavs, policy, folder):
    """Import one crop and place its UAVs with each positioner: a row for the tables."""
    row = dict(crop, set=set_name, uavs=uavs, rewards={}, seconds={}, errors={})
    scenario = os.path.join(folder, "crop%d-%s.json" % (crop["index"], set_name))
    made = subprocess.run([sim, "import", "--from", "osm", args.file,
                           "--center", "%.6f,%.6f" % (crop["lat"], crop["lon"]),
                           "--size", "%gx%g" % args.size, "--ues", str(args.ues),
                           "--ue-groups", str(crop["groups"]), "--uavs", str(uavs),
                           "--seed", str(crop["ue_seed"]), "--out", scenario],
                          capture_output=True, text=True)
    if made.returncode != 0:
        row["refused"] = "exit %d: %s" % (made.returncode, first_error(made.stderr))
        return row
    row["beyond"] = "reaches beyond the data" in made.stderr
    with open(scenario) as f:
        row["buildings"] = len(json.load(f).get("buildings", []))
    for positioner in POSITIONERS:
        command = [sim, "position", "--scenario", scenario, "--positioner", positioner, "--json"]
        if positioner == "rl":
            command += ["--policy", policy]
        started = time.monotonic()
        done = subprocess.run(command, capture_output=True, text=True)
        row["seconds"][positioner] = time.monotonic() - started
        try:
            if done.returncode != 0:
                raise ValueError("exit %d: %s" % (done.returncode, first_error(done.stderr)))
            row["rewards"][positioner] = float(json.loads(done.stdout)["reward"])
        except (ValueError, KeyError, TypeError) as error:
            row["errors"][positioner] = str(error)
    return row


def ratio_of(row):
    rl, oracle = row["rewards"].get("rl"), row["rewards"].get("oracle")
    if rl is None or oracle is None:
        return None
    return rl / oracle if oracle > 0 else 1.0


def print_row(row):
    centre = "%.6f,%.6f" % (row["lat"], row["lon"])
    if "refused" in row:
        print("| %d | %s | refused | %s |" % (row["index"], centre, " | ".join(["-"] * 9)),
              flush=True)
        return
    cells = [str(row["index"]), centre + (" (beyond the data)" if row["beyond"] else ""),
             str(row["buildings"]), str(row["groups"]), str(row["uavs"])]
    for p in POSITIONERS:
        cells.append("%.4f" % row["rewards"][p] if p in row["rewards"] else "error")
    ratio = ratio_of(row)
    cells.append("%.3f" % ratio if ratio is not None else "-")
    for p in POSITIONERS:
        cells.append("%.2f" % row["seconds"][p])
    print("| " + " | ".join(cells) + " |", flush=True)
    for p, error in row["errors"].items():
        print("bench_real_places: crop %d (%s), %s: %s" % (row["index"], row["set"], p, error),
              file=sys.stderr, flush=True)


def summary(rows, crops):
    refused = [r for r in rows if "refused" in r]
    scored = [r for r in rows if ratio_of(r) is not None]
    failed = len(rows) - len(refused) - len(scored)
    head = "%d crops: %d placed" % (crops, len(scored))
    if refused:
        head += ", %d refused by the importer (%s)" % (
            len(refused), "; ".join("crop %d: %s" % (r["index"], r["refused"]) for r in refused))
    if failed:
        head += ", %d with a failed positioner" % failed
    if not scored:
        return head + "; nothing to summarise"
    ratios = [ratio_of(r) for r in scored]
    worst = min(scored, key=ratio_of)
    reached = sum(r >= TARGET for r in ratios)
    rl_seconds = [r["seconds"]["rl"] for r in scored]
    slowest = max(scored, key=lambda r: r["seconds"]["rl"])
    centroid = [r["rewards"]["centroid"] / r["rewards"]["oracle"] for r in scored
                if "centroid" in r["rewards"] and r["rewards"]["oracle"] > 0]
    text = ("%s; rl >= %.2f of the oracle in %d of %d (%.0f%%), median ratio %.3f, worst %.3f "
            "(crop %d); rl seconds per placement: median %.2f, max %.2f (crop %d); oracle "
            "seconds median %.2f" %
            (head, TARGET, reached, len(ratios), 100.0 * reached / len(ratios),
             statistics.median(ratios), ratio_of(worst), worst["index"],
             statistics.median(rl_seconds), slowest["seconds"]["rl"], slowest["index"],
             statistics.median(r["seconds"]["oracle"] for r in scored)))
    if centroid:
        text += "; centroid / oracle median %.3f, worst %.3f" % (
            statistics.median(centroid), min(centroid))
    return text


def shown_path(path):
    """A path as the reproducing command gives it: relative to the repository when inside it."""
    full = os.path.abspath(path)
    inside = os.path.relpath(full, REPO)
    return full if inside.startswith("..") else inside


def main():
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--crops", type=int, default=24, help="crops (default 24)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the crops' draw (default 1)")
    parser.add_argument("--size", default="300x300", help="venue WxD in metres (default 300x300)")
    parser.add_argument("--ues", type=int, default=20, help="UEs per crop (default 20)")
    parser.add_argument("--file", default=None,
                        help="OpenStreetMap extract (default %s)" % DEFAULT_FILE)
    parser.add_argument("--box", help="the data box of --file, MINLON,MINLAT,MAXLON,MAXLAT "
                        "(default: the shipped extract's)")
    parser.add_argument("--sets", default="one,several", help="one,several (default both)")
    parser.add_argument("--many-uavs", default="2-4",
                        help="UAVs of a crop of the several-UAV set, MIN-MAX (default 2-4)")
    parser.add_argument("--jobs", type=int, default=1, help="crops at a time (default 1)")
    parser.add_argument("--build", default=os.path.join(REPO, "build"), help="build folder")
    args = parser.parse_args()

    if args.crops < 1:
        fail("--crops: must be at least 1")
    if args.seed < 0:
        fail("--seed: must be non-negative")
    if args.ues < 1:
        fail("--ues: must be at least 1")
    if args.jobs < 1:
        fail("--jobs: must be at least 1")
    args.size = size_of(args.size)
    sets = sets_of(args.sets)
    many = range_of(args.many_uavs, "--many-uavs")
    if args.file is None:
        args.file = os.path.join(REPO, DEFAULT_FILE)
        args.box = box_of(args.box) if args.box else DEFAULT_BOX
    elif args.box is None:
        fail("--box: give the data box of %s (MINLON,MINLAT,MAXLON,MAXLAT)" % args.file)
    else:
        args.box = box_of(args.box)
    if not os.path.isfile(args.file):
        fail("--file: %s: no such file" % args.file)
    sim = os.path.join(args.build, "bin", "rlpos-sim")
    if not os.access(sim, os.X_OK):
        fail("%s not found: build first (or pass --build)" % sim)
    policies = {}
    for s in sets:
        folder = os.path.join(REPO, "policies", SETS[s][1])
        low, high = policy_uavs(folder)
        wanted = (1, 1) if s == "one" else many
        if not (low <= wanted[0] and wanted[1] <= high):
            fail("--many-uavs: %s places %d-%d UAVs, not %d-%d" %
                 (SETS[s][1], low, high, wanted[0], wanted[1]))
        policies[s] = folder

    crops = draw_crops(args, many)
    started = time.monotonic()
    rows = {s: [] for s in sets}
    with tempfile.TemporaryDirectory(prefix="bench_real_places.") as folder, \
            concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = {s: [pool.submit(run_crop, args, sim, c, s, 1 if s == "one" else c["many"],
                                   policies[s], folder) for c in crops] for s in sets}
        for s in sets:
            print("## %s: rlpos-sim position --positioner rl --policy policies/%s, oracle, "
                  "centroid; %d crops of %gx%g m, %d UEs" %
                  (SETS[s][0], SETS[s][1], len(crops), args.size[0], args.size[1], args.ues))
            print()
            print("| crop | centre (lat,lon) | buildings | UE groups | UAVs | rl | oracle | "
                  "centroid | rl / oracle | rl s | oracle s | centroid s |")
            print("|---|---|---|---|---|---|---|---|---|---|---|---|")
            for future in futures[s]:
                row = future.result()
                rows[s].append(row)
                print_row(row)
            print()
            print(summary(rows[s], len(crops)))
            print()
    wall = time.monotonic() - started

    command = ["scripts/bench_real_places.py", "--crops", str(args.crops), "--seed",
               str(args.seed), "--size", "%gx%g" % args.size, "--ues", str(args.ues),
               "--file", shown_path(args.file)]
    if args.box != DEFAULT_BOX or shown_path(args.file) != DEFAULT_FILE:
        command += ["--box", ",".join(str(v) for v in args.box)]
    command += ["--sets", ",".join(sets)]
    if "several" in sets:
        command += ["--many-uavs", "%d-%d" % many]
    command += ["--jobs", str(args.jobs)]
    if os.path.abspath(args.build) != os.path.join(REPO, "build"):
        command += ["--build", shown_path(args.build)]
    print("%.0f s wall, %d crop(s) at a time; reproduce from the repository root with:" %
          (wall, args.jobs))
    print("  " + " ".join(command))
    failed = any(r["errors"] for s in sets for r in rows[s])
    placed = any(ratio_of(r) is not None for s in sets for r in rows[s])
    return 1 if failed or not placed else 0


if __name__ == "__main__":
    sys.exit(main())
