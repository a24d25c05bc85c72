#!/bin/bash
# scripts/bench_agents.py --oracle-cache with a bad FILE: one line on stderr naming the file and
# what is wrong, exit 1, before anything trains (--build points nowhere, so a run that went on
# would fail differently), and the file left as it was.
# usage: bench_agents_cache.sh REPO
set -u
repo=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

# expect NAME CACHE PREFIX: the run's stderr must be one line that starts with PREFIX (the
# rest is Python's or the C library's own wording), its status 1.
expect() {
  local name=$1 cache=$2 want=$3
  python3 "$repo/scripts/bench_agents.py" --build "$tmp/no-build" --scenarios a --seeds 1 \
    --algorithms dqn --oracle-cache "$cache" >"$tmp/out" 2>"$tmp/err"
  local status=$?
  local got
  got=$(cat "$tmp/err")
  if [ "$status" -ne 1 ] || [ "$(wc -l <"$tmp/err")" -ne 1 ] || [ "${got#"$want"}" = "$got" ]; then
    echo "FAIL $name: status $status, stderr:"
    cat "$tmp/err"
    echo "expected status 1 and one line starting: $want"
    failures=$((failures + 1))
  fi
}

printf '{"k": ' >"$tmp/truncated.json"
expect truncated "$tmp/truncated.json" \
  "bench_agents: --oracle-cache $tmp/truncated.json: not JSON: "
[ "$(cat "$tmp/truncated.json")" = '{"k": ' ] || { echo "FAIL truncated: the file changed"; failures=$((failures + 1)); }

printf '{"k": "fast"}' >"$tmp/text.json"
expect not_rewards "$tmp/text.json" \
  "bench_agents: --oracle-cache $tmp/text.json: not an object of rewards"

expect missing_folder "$tmp/nope/oracles.json" \
  "bench_agents: --oracle-cache $tmp/nope/oracles.json: folder $tmp/nope does not exist"
[ ! -e "$tmp/nope" ] || { echo "FAIL missing_folder: the folder was created"; failures=$((failures + 1)); }

mkdir "$tmp/a-folder"
expect a_folder "$tmp/a-folder" "bench_agents: --oracle-cache $tmp/a-folder: "

[ "$failures" -eq 0 ] && echo "bench_agents --oracle-cache: 4 bad caches refused"
exit $((failures > 0))
