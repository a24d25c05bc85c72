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
algorithm (named policy, positioner) and number of UAVs. With --track-distributions
(track_distributions.csv: scenario, positioner, metric, p_is, x, p) it draws
track_distributions_<scenario>.png: per track positioner, the distribution over the RngRuns of
each run's time means (reward, throughput, delay, outage share), one panel per metric. With
--track-series (track_series.csv: scenario, positioner, interval, time_s, runs, scored, reward,
throughput_mbps, delay_ms, los_share, demands_met_share) it draws track_series_<scenario>.png:
each interval's metrics averaged over the runs, one line per positioner, the unscored warm-up
shaded.

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


# The track metrics the figures show, in panel order: CSV key, axis label.
TRACK_DISTRIBUTIONS = [
    ("mean_reward", "Time-mean reward"),
    ("mean_throughput_mbps", "Time-mean aggregate throughput (Mbit/s)"),
    ("mean_delay_ms", "Time-mean delay (ms)"),
    ("outage_share", "Outage share (UE-intervals)"),
]
TRACK_SERIES = [
    ("reward", "Reward"),
    ("throughput_mbps", "Aggregate throughput (Mbit/s)"),
    ("los_share", "Share of UEs in LoS"),
    ("demands_met_share", "Share of UEs whose demand is met"),
]


def read_track_distributions(path):
    """{scenario: {metric: (above, {positioner: ([x], [p])})}}, in the order of the file."""
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            metrics = curves.setdefault(row["scenario"], {})
            above, by_positioner = metrics.setdefault(row["metric"], (row["p_is"] == "above", {}))
            xs, ps = by_positioner.setdefault(row["positioner"], ([], []))
            xs.append(float(row["x"]))
            ps.append(float(row["p"]))
    return curves


def read_track_series(path):
    """{scenario: {positioner: [row dict with floats]}}, intervals in order."""
    series = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            point = {"time_s": float(row["time_s"]), "scored": row["scored"] == "1"}
            for key, _ in TRACK_SERIES:
                point[key] = float(row[key])
            series.setdefault(row["scenario"], {}).setdefault(row["positioner"], []).append(point)
    return series


def legend_under_title(figure, panel, title):
    """One legend for every panel, between the title and the panels, where it hides no line."""
    handles, labels = panel.get_legend_handles_labels()
    figure.suptitle(title)
    figure.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, 0.955),
                  ncol=min(len(labels), 5), fontsize="small", frameon=False)
    rows = (len(labels) + 4) // 5
    figure.tight_layout(rect=(0, 0, 1, 0.93 - 0.035 * (rows - 1)))


def plot_track_distributions(plt, metrics, title, path):
    """One panel per track metric: a step curve per positioner over its RngRuns."""
    from matplotlib.ticker import MaxNLocator

    shown = [(key, label) for key, label in TRACK_DISTRIBUTIONS if key in metrics]
    columns = 2 if len(shown) > 1 else 1
    rows = (len(shown) + columns - 1) // columns
    figure, axes = plt.subplots(rows, columns, figsize=(6.4 * columns / 1.4, 3.4 * rows),
                                squeeze=False)
    for panel, (key, label) in zip(axes.flat, shown):
        above, by_positioner = metrics[key]
        for positioner, (xs, ps) in by_positioner.items():
            panel.plot([xs[0]] + xs, [1.0 if above else 0.0] + ps, drawstyle="steps-post",
                       label=positioner)
        panel.set_xlabel(label)
        panel.xaxis.set_major_locator(MaxNLocator(6))
        panel.set_ylabel("P(X > x)" if above else "P(X \u2264 x)")
        panel.set_ylim(-0.02, 1.02)
        panel.grid(True, alpha=0.3)
    for panel in list(axes.flat)[len(shown):]:
        panel.set_visible(False)
    legend_under_title(figure, axes.flat[0], title)
    save_atomically(figure, path)
    plt.close(figure)
    print(f"wrote {path}", flush=True)


def plot_track_series(plt, by_positioner, title, path):
    """One panel per interval metric against time; the warm-up (unscored) shaded."""
    figure, axes = plt.subplots(2, 2, figsize=(9.6, 6.4), sharex=True)
    for panel, (key, label) in zip(axes.flat, TRACK_SERIES):
        for positioner, points in by_positioner.items():
            panel.plot([p["time_s"] for p in points], [p[key] for p in points],
                       linewidth=1.2, label=positioner)
        unscored = [p["time_s"] for points in by_positioner.values() for p in points
                    if not p["scored"]]
        if unscored:
            panel.axvspan(0.0, max(unscored), color="grey", alpha=0.15, linewidth=0)
        panel.set_ylabel(label)
        panel.grid(True, alpha=0.3)
    for panel in axes[1]:
        panel.set_xlabel("Time (s), at the end of each decision interval")
    legend_under_title(figure, axes[0][0], title)
    save_atomically(figure, path)
    plt.close(figure)
    print(f"wrote {path}", flush=True)


def plot_optimality(plt, curves, title, path):
    """The ratio's CDF per series, with the 0.95 line."""
    figure, axes = step_curves(plt, curves, 0.0)
    axes.axvline(0.95, color="grey", linestyle="--", linewidth=1)
    finish_step_plot(plt, figure, axes, "reward / oracle reward", "P(ratio \u2264 x)", title,
                     path)


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


def replace_atomically(path, write, mode, suffix=""):
    """write(file) into a temporary file beside path, renamed over path once whole: a reader sees
    the old file or the new one, never a part (bench_generality.py writes its campaign so too)."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, temp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".", suffix=suffix,
                                dir=folder)
    try:
        with os.fdopen(fd, mode) as f:
            write(f)
        os.chmod(temp, 0o644)
        os.replace(temp, path)
    except BaseException:
        if os.path.exists(temp):
            os.unlink(temp)
        raise


def save_atomically(figure, path):
    replace_atomically(path, lambda f: figure.savefig(f, format="png", dpi=120), "wb", ".tmp")


def step_curves(plt, curves, start_p):
    """A figure of one step curve per series; each starts at p = start_p left of its first point."""
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    for name, (xs, ps) in curves.items():
        axes.plot([xs[0]] + xs, [start_p] + ps, drawstyle="steps-post", label=name)
    return figure, axes


def finish_step_plot(plt, figure, axes, xlabel, ylabel, title, path):
    """Labels, the [0, 1] range, grid and legend, and the figure written to path."""
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


def plot(plt, curves, start_p, xlabel, ylabel, title, path):
    """One step curve per positioner; each starts at p = start_p left of its first point."""
    figure, axes = step_curves(plt, curves, start_p)
    finish_step_plot(plt, figure, axes, xlabel, ylabel, title, path)


def plot_per_scenario(plt, by_scenario, plot_one, prefix, what, out_dir, name):
    """plot_one(plt, data, title, path) per scenario, titled "<prefix>scenario <s>: <what>", into
    out_dir/<name>_<file stem>.png."""
    used = set()
    for scenario, data in by_scenario.items():
        plot_one(plt, data, f"{prefix}scenario {scenario}: {what}",
                 os.path.join(out_dir, f"{name}_{file_stem(scenario, used)}.png"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--throughput-ccdf", required=True, help="throughput_ccdf.csv")
    parser.add_argument("--delay-cdf", required=True, help="delay_cdf.csv")
    parser.add_argument("--out-dir", required=True, help="folder for the PNGs")
    parser.add_argument("--title", default="", help="figure title prefix (campaign name)")
    parser.add_argument("--learning-curves", help="learning_curves.csv (optional)")
    parser.add_argument("--optimality-cdf", help="optimality_cdf.csv (optional)")
    parser.add_argument("--track-distributions", help="track_distributions.csv (optional)")
    parser.add_argument("--track-series", help="track_series.csv (optional)")
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
        plot_per_scenario(plt, read_learning_curves(args.learning_curves), plot_learning, prefix,
                          "learning curve", args.out_dir, "learning_curve")
    if args.optimality_cdf:
        curves = read_optimality(args.optimality_cdf)
        if curves:
            plot_optimality(plt, curves, f"{prefix}optimality: each placement against the oracle",
                            os.path.join(args.out_dir, "optimality_cdf.png"))
    if args.track_distributions:
        plot_per_scenario(plt, read_track_distributions(args.track_distributions),
                          plot_track_distributions, prefix, "track runs over their RngRuns",
                          args.out_dir, "track_distributions")
    if args.track_series:
        plot_per_scenario(plt, read_track_series(args.track_series), plot_track_series, prefix,
                          "track runs over time (mean of RngRuns)", args.out_dir, "track_series")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (OSError, ValueError) as error:
        print(f"plot_campaign.py: {error}", file=sys.stderr)
        sys.exit(1)
