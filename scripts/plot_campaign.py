#!/usr/bin/env python3
"""Draws a campaign report's figures from its curve CSVs (the paper's Figures 3-7).

`rlpos-campaign report` writes throughput_ccdf.csv and delay_cdf.csv (columns: scenario,
positioner, x, p) and runs this script on them; per scenario it draws one throughput CCDF and
one delay CDF, one step curve per positioner, into the output folder as
throughput_ccdf_<scenario>.png and delay_cdf_<scenario>.png. With --learning-curves
(learning_curves.csv: scenario, label, episode, phase, total_reward, mean_loss, epsilon) it also
draws learning_curve_<scenario>.png: reward and loss per training episode, one line per train
job. With --optimality-cdf (optimality_cdf.csv: algorithm, uavs, ratio, p) it draws
optimality_cdf.png: the CDF of each placement's reward over the oracle's, one step curve per
algorithm (named policy, positioner) and number of UAVs.

Prints "wrote <path>" for every file written. Exit status: 0 done, 1 error, 2 bad arguments,
3 matplotlib is not available (the caller may try another interpreter).
"""

import argparse
import csv
import os
import re
import sys
import tempfile

NO_MATPLOTLIB = 3


def read_curves(path):
    """{scenario: {positioner: ([x], [p])}}, both in the order of the file."""
    curves = {}
    with open(path, newline="") as f:
        reader = csv.reader(f)
        next(reader, None)  # header
        for row in reader:
            if len(row) < 4:
                continue
            scenario, positioner, x, p = row[0], row[1], float(row[2]), float(row[3])
            xs, ps = curves.setdefault(scenario, {}).setdefault(positioner, ([], []))
            xs.append(x)
            ps.append(p)
    return curves


def read_learning_curves(path):
    """{scenario: {label: [(episode, total_reward, mean_loss)]}}, training episodes only."""
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["phase"] != "train":
                continue
            points = curves.setdefault(row["scenario"], {}).setdefault(row["label"], [])
            points.append((int(row["episode"]), float(row["total_reward"]),
                           float(row["mean_loss"])))
    return curves


def read_optimality(path):
    """{"<algorithm>, <k> UAV(s)": ([ratio], [p])}, in the order of the file."""
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            uavs = int(row["uavs"])
            name = f"{row['algorithm'] or '-'}, {uavs} UAV{'' if uavs == 1 else 's'}"
            xs, ps = curves.setdefault(name, ([], []))
            xs.append(float(row["ratio"]))
            ps.append(float(row["p"]))
    return curves


def plot_optimality(plt, curves, title, path):
    """The ratio's CDF per series, with the 0.95 line."""
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    for name, (xs, ps) in curves.items():
        axes.plot([xs[0]] + xs, [0.0] + ps, drawstyle="steps-post", label=name)
    axes.axvline(0.95, color="grey", linestyle="--", linewidth=1)
    axes.set_xlabel("reward / oracle reward")
    axes.set_ylabel("P(ratio \u2264 x)")
    axes.set_ylim(-0.02, 1.02)
    axes.set_title(title)
    axes.grid(True, alpha=0.3)
    axes.legend(fontsize="small")
    figure.tight_layout()
    save_atomically(figure, path)
    plt.close(figure)
    print(f"wrote {path}", flush=True)


def plot_learning(plt, curves, title, path):
    """Reward (top) and mean loss (bottom, log scale) per training episode, one line per job."""
    figure, (reward, loss) = plt.subplots(2, 1, figsize=(6.4, 5.6), sharex=True)
    for label, points in curves.items():
        episodes = [p[0] for p in points]
        reward.plot(episodes, [p[1] for p in points], marker=".", label=label)
        losses = [(e, p[2]) for e, p in zip(episodes, points) if p[2] > 0]
        if losses:
            loss.plot([e for e, _ in losses], [v for _, v in losses], marker=".", label=label)
    reward.set_ylabel("Episode reward")
    reward.set_title(title)
    reward.grid(True, alpha=0.3)
    reward.legend(fontsize="small")
    loss.set_ylabel("Mean loss (DQN: TD, PPO: clipped objective, SAC: Q)")
    loss.set_yscale("log")
    loss.set_xlabel("Training episode")
    loss.grid(True, alpha=0.3)
    figure.tight_layout()
    save_atomically(figure, path)
    plt.close(figure)
    print(f"wrote {path}", flush=True)


def file_stem(scenario, used):
    stem = re.sub(r"[^A-Za-z0-9._-]+", "_", scenario).strip("._") or "scenario"
    candidate, n = stem, 2
    while candidate in used:
        candidate, n = f"{stem}_{n}", n + 1
    used.add(candidate)
    return candidate


def save_atomically(figure, path):
    folder = os.path.dirname(os.path.abspath(path))
    fd, temp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".", suffix=".tmp",
                                dir=folder)
    try:
        with os.fdopen(fd, "wb") as f:
            figure.savefig(f, format="png", dpi=120)
        os.chmod(temp, 0o644)
        os.replace(temp, path)
    except BaseException:
        if os.path.exists(temp):
            os.unlink(temp)
        raise


def plot(plt, curves, start_p, xlabel, ylabel, title, path):
    """One step curve per positioner; each starts at p = start_p left of its first point."""
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    for positioner, (xs, ps) in curves.items():
        axes.plot([xs[0]] + xs, [start_p] + ps, drawstyle="steps-post", label=positioner)
    axes.set_xlabel(xlabel)
    axes.set_ylabel(ylabel)
    axes.set_ylim(-0.02, 1.02)
    axes.set_title(title)
    axes.grid(True, alpha=0.3)
    axes.legend(fontsize="small")
    figure.tight_layout()
    save_atomically(figure, path)
    plt.close(figure)
    print(f"wrote {path}", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--throughput-ccdf", required=True, help="throughput_ccdf.csv")
    parser.add_argument("--delay-cdf", required=True, help="delay_cdf.csv")
    parser.add_argument("--out-dir", required=True, help="folder for the PNGs")
    parser.add_argument("--title", default="", help="figure title prefix (campaign name)")
    parser.add_argument("--learning-curves", help="learning_curves.csv (optional)")
    parser.add_argument("--optimality-cdf", help="optimality_cdf.csv (optional)")
    args = parser.parse_args()

    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as error:
        print(f"plot_campaign.py: matplotlib is not available: {error}", file=sys.stderr)
        return NO_MATPLOTLIB

    throughput = read_curves(args.throughput_ccdf)
    delay = read_curves(args.delay_cdf)
    prefix = f"{args.title}: " if args.title else ""
    used = set()
    for scenario in list(throughput) + [s for s in delay if s not in throughput]:
        stem = file_stem(scenario, used)
        if scenario in throughput:
            plot(plt, throughput[scenario], 1.0, "Aggregate throughput (Mbit/s)", "P(X > x)",
                 f"{prefix}scenario {scenario}: throughput CCDF",
                 os.path.join(args.out_dir, f"throughput_ccdf_{stem}.png"))
        if scenario in delay:
            plot(plt, delay[scenario], 0.0, "Mean delay (ms)", "P(X \u2264 x)",
                 f"{prefix}scenario {scenario}: delay CDF",
                 os.path.join(args.out_dir, f"delay_cdf_{stem}.png"))
    if args.learning_curves:
        used = set()
        for scenario, curves in read_learning_curves(args.learning_curves).items():
            plot_learning(plt, curves, f"{prefix}scenario {scenario}: learning curve",
                          os.path.join(args.out_dir,
                                       f"learning_curve_{file_stem(scenario, used)}.png"))
    if args.optimality_cdf:
        curves = read_optimality(args.optimality_cdf)
        if curves:
            plot_optimality(plt, curves, f"{prefix}optimality: each placement against the oracle",
                            os.path.join(args.out_dir, "optimality_cdf.png"))
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (OSError, ValueError) as error:
        print(f"plot_campaign.py: {error}", file=sys.stderr)
        sys.exit(1)
