"""What the bench_*.py scripts in this folder share: the machine's CPU for their reports, their
rows written as CSV, and the options of the track benchmarks."""
import csv
import platform


def cpu_model():
    try:
        with open("/proc/cpuinfo") as info:
            for line in info:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def write_csv(path, rows):
    """Dicts of the same keys as CSV, a header of the first's keys."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def add_track_run_arguments(parser, per_style, duration, run_help):
    """--per-style, --duration, --interval and --run of a track benchmark (bench_tracking.py,
    bench_track_cost.py), with their defaults."""
    parser.add_argument("--per-style", type=int, default=per_style,
                        help="scenarios per style, the mobility models in turn (default %d)"
                        % per_style)
    parser.add_argument("--duration", type=float, default=duration,
                        help="s per run (default %g)" % duration)
    parser.add_argument("--interval", type=float, default=1.0,
                        help="env.decision_interval, s (default 1)")
    parser.add_argument("--run", type=int, default=1, help=run_help)
