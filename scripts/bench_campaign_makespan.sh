#!/usr/bin/env bash
# Makespan of `rlpos-campaign run` against `xargs -P N` running the same rlpos-sim jobs, side by
# side on this machine, and the runner's dispatch overhead per job. Prints figures only.
#   scripts/bench_campaign_makespan.sh [BUILD_DIR] [CAMPAIGN] [N] [REPEATS]
# Defaults: build, campaigns/mini.json, the number of cores, 1.
# xargs gets the runner's own command lines (read back from its database, positions bound) in
# two waves, train and position jobs then evals, since xargs knows no dependencies. Repeats
# alternate the two, so that a busy neighbour on a shared machine hits both alike.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "${1:-"$here/build"}/bin" && pwd)
campaign=${2:-"$here/campaigns/mini.json"}
n=${3:-$(nproc)}
repeats=${4:-1}
for tool in rlpos-campaign rlpos-sim; do
  [ -x "$bin/$tool" ] || { echo "bench: $bin/$tool not built (run scripts/bootstrap)" >&2; exit 1; }
done
work=$(mktemp -d "${TMPDIR:-/tmp}/rlpos-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
now() { date +%s.%N; }

runner_times=() xargs_times=()
for r in $(seq 1 "$repeats"); do
  db=$work/run$r/rlpos.db
  start=$(now)
  "$bin/rlpos-campaign" run "$campaign" --workers "$n" --db "$db" --no-progress >/dev/null 2>&1
  runner_times+=("$(echo "$(now) - $start" | bc -l)")

  # The same jobs as shell scripts, one per job, in two waves: each replays the command line the
  # worker composed (command.txt in the attempt's folder) on a copy of its scenario file.
  mkdir -p "$work/xargs$r/first" "$work/xargs$r/evals"
  /usr/bin/python3 - "$work/run$r/work" "$work/xargs$r" <<'PY'
import glob, os, shlex, shutil, sys
runs, out = sys.argv[1:]
for i, command in enumerate(sorted(glob.glob(f"{runs}/**/attempt1/command.txt", recursive=True))):
    folder = os.path.dirname(command)
    copy = f"{out}/j{i}"
    os.makedirs(copy)
    shutil.copy(f"{folder}/scenario.json", copy)
    args = [a.replace(folder, copy) for a in open(command).read().splitlines()]
    wave = "evals" if args[1] == "eval" else "first"
    with open(f"{out}/{wave}/{i:05d}.sh", "w") as f:
        f.write(" ".join(shlex.quote(a) for a in args) + " >/dev/null 2>&1\n")
PY
  start=$(now)
  for wave in first evals; do
    find "$work/xargs$r/$wave" -name '*.sh' | sort | xargs -P "$n" -n 1 bash
  done
  xargs_times+=("$(echo "$(now) - $start" | bc -l)")
done

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
runner=$(median "${runner_times[@]}")
xargs_s=$(median "${xargs_times[@]}")
db=$work/run1/rlpos.db
jobs=$(sqlite3 "$db" "SELECT COUNT(*) FROM jobs")
# Dispatch overhead: on each worker, the idle time between the end of one job (result recorded)
# and the start of its next (assignment recorded), over all jobs.
gap=$(sqlite3 "$db" "WITH o AS (SELECT worker_id, started_at, finished_at,
    LAG(finished_at) OVER (PARTITION BY worker_id ORDER BY started_at) AS prev FROM jobs)
  SELECT printf('%.1f', 1000.0 * AVG(started_at - prev)) FROM o WHERE prev IS NOT NULL")
printf 'campaign %s: %s jobs, %s workers, %s repeat(s)\n' "$(basename "$campaign")" "$jobs" "$n" "$repeats"
printf '%-28s %10s\n' "" "makespan s"
printf '%-28s %10.1f\n' "rlpos-campaign run" "$runner" "xargs -P $n (2 waves)" "$xargs_s"
printf 'runner / xargs: %.3f (%+.1f %%)\n' "$(echo "$runner / $xargs_s" | bc -l)" \
  "$(echo "100 * ($runner - $xargs_s) / $xargs_s" | bc -l)"
printf 'dispatch gap per job (result in -> next job assigned, same worker): %s ms\n' "$gap"
printf 'makespan difference per job: %+.2f s\n' \
  "$(echo "($runner - $xargs_s) / $jobs" | bc -l)"
