#!/usr/bin/env python3
"""Where a build's time went: compile and link seconds per target, and the slowest files.

Usage: scripts/build_times.py [BUILD] [--top N] [--compare OTHER_BUILD]
BUILD is a build folder (its .ninja_log: wall seconds per output; default build/) or a CPU log
written by scripts/lib/cpu_time_launcher (CPU seconds per output, which a busy machine disturbs
far less). Each output counts once, at its latest build. A target's time is the sum of its
objects' compile times plus its link; with -j N the wall time is about the sum over N. --compare
prints a second build's figures beside, target by target, with the ratio (this build / other).
Run it after a full build from scratch: an incremental build logs only what it rebuilt.

A CPU log of a whole build from scratch:
  RLPOS_CPU_LOG=$PWD/cpu.log cmake -S . -B build-timed -G Ninja \\
      -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/scripts/lib/cpu_time_launcher \\
      -DCMAKE_CXX_LINKER_LAUNCHER=$PWD/scripts/lib/cpu_time_launcher
  RLPOS_CPU_LOG=$PWD/cpu.log cmake --build build-timed
  scripts/build_times.py cpu.log
"""
import argparse
import os
import re
import sys
from collections import defaultdict

# "common/store/CMakeFiles/rlpos_store.dir/x.cc.o" -> "rlpos_store"
OBJECT = re.compile(r'CMakeFiles/([^/]+)\.dir/(.+)\.o$')


def read_cpu_log(path):
    """Returns {output: (0, cpu_ms)} from a cpu_time_launcher log, the latest entry of each."""
    entries = {}
    try:
        with open(path, encoding='utf-8') as log:
            for number, line in enumerate(log, 1):
                fields = line.rstrip('\n').split('\t')
                try:
                    entries[fields[2]] = (0, round(float(fields[0]) * 1000))
                except (IndexError, ValueError):
                    sys.exit(f'build_times.py: error: {path}:{number}: not a CPU log line')
    except OSError as e:
        sys.exit(f'build_times.py: error: {path}: {e.strerror}')
    return entries


def read_log(build):
    """Returns {output: (start_ms, end_ms)}, the latest entry of each output."""
    if os.path.isfile(build):
        return read_cpu_log(build)
    build_dir = build
    path = os.path.join(build_dir, '.ninja_log')
    try:
        with open(path, encoding='utf-8') as log:
            header = log.readline()
            if not header.startswith('# ninja log v'):
                sys.exit(f'build_times.py: error: {path}: not a ninja log')
            entries = {}
            for line in log:
                fields = line.rstrip('\n').split('\t')
                if len(fields) != 5:
                    continue
                start, end, _, output, _ = fields
                entries[output] = (int(start), int(end))
            return entries
    except OSError as e:
        sys.exit(f'build_times.py: error: {path}: {e.strerror}')


def target_of(output):
    match = OBJECT.search(output)
    if match:
        return match.group(1), 'compile'
    base = os.path.basename(output)
    if base.endswith(('.a', '.so')) or '/bin/' in '/' + output or output.startswith('bin/'):
        name = re.sub(r'^lib|\.(a|so)$', '', base)
        return name, 'link'
    return None, None


def summarise(entries):
    """Returns ({target: {'compile': s, 'link': s, 'files': n}}, [(seconds, object)], wall_s)."""
    targets = defaultdict(lambda: {'compile': 0.0, 'link': 0.0, 'files': 0})
    files = []
    for output, (start, end) in entries.items():
        seconds = (end - start) / 1000
        target, kind = target_of(output)
        if target is None:
            continue
        targets[target][kind] += seconds
        if kind == 'compile':
            targets[target]['files'] += 1
            files.append((seconds, output))
    if not entries:
        return targets, files, 0.0
    wall = (max(e for _, e in entries.values()) - min(s for s, _ in entries.values())) / 1000
    return targets, sorted(files, reverse=True), wall


def total(t):
    return t['compile'] + t['link']


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('build_dir', nargs='?', default='build', metavar='BUILD')
    parser.add_argument('--top', type=int, default=15, help='slowest files to list (15)')
    parser.add_argument('--compare', metavar='OTHER_BUILD')
    args = parser.parse_args()

    targets, files, wall = summarise(read_log(args.build_dir))
    other = summarise(read_log(args.compare)) if args.compare else None
    cpu = sum(total(t) for t in targets.values())
    cpu_log = os.path.isfile(args.build_dir)
    print(f'{args.build_dir}: {len(files)} objects, {cpu:.0f} s of compile and link' +
          ('' if cpu_log else f', {wall:.0f} s wall for the last build of each output'))
    if other:
        other_cpu = sum(total(t) for t in other[0].values())
        print(f'{args.compare}: {len(other[1])} objects, {other_cpu:.0f} s of compile and link; '
              f'ratio {cpu / max(other_cpu, 1e-9):.2f}')
    print()
    header = f'{"target":<36} {"files":>5} {"compile s":>10} {"link s":>7} {"total s":>8}'
    print(header + ('  other s  ratio' if other else ''))
    names = sorted(targets, key=lambda n: total(targets[n]), reverse=True)
    if other:
        names += sorted(set(other[0]) - set(targets))
    for name in names:
        t = targets.get(name, {'compile': 0.0, 'link': 0.0, 'files': 0})
        line = f'{name:<36} {t["files"]:>5} {t["compile"]:>10.1f} {t["link"]:>7.1f} {total(t):>8.1f}'
        if other:
            o = total(other[0][name]) if name in other[0] else 0.0
            line += f' {o:>8.1f}  ' + (f'{total(t) / o:5.2f}' if o > 0 else '    -')
        print(line)
    print(f'\nslowest {args.top} objects:')
    for seconds, output in files[:args.top]:
        print(f'{seconds:8.1f}  {output}')


if __name__ == '__main__':
    try:
        main()
    except BrokenPipeError:  # piped into head
        sys.exit(0)
