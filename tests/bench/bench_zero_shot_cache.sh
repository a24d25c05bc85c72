#!/bin/bash
# scripts/bench_zero_shot.py --oracle-cache: a bad FILE is refused in one line naming it, exit 2,
# before anything runs, and left as it was; a good one is written, read back instead of a new
# search, and missed by a scenario whose bytes changed.
# usage: bench_zero_shot_cache.sh REPO BUILD PYTHON (PYTHON: the interpreter the binding is for)
set -u
repo=$1 build=$2 py=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
bench() { PYTHONPATH="$build/python" "$py" "$repo/scripts/bench_zero_shot.py" "$@"; }

# expect NAME CACHE PREFIX: stderr is one line starting with PREFIX, status 2.
expect() {
  local name=$1 cache=$2 want=$3
  bench --build "$tmp/no-build" --policy "$tmp/none" --scenarios "$tmp/none" \
    --oracle-cache "$cache" >"$tmp/out" 2>"$tmp/err"
  local status=$?
  local got
  got=$(cat "$tmp/err")
  if [ "$status" -ne 2 ] || [ "$(wc -l <"$tmp/err")" -ne 1 ] || [ "${got#"$want"}" = "$got" ]; then
    fail "$name: status $status, stderr: $got (expected status 2 and: $want)"
  fi
}
printf '{"k": ' >"$tmp/truncated.json"
expect truncated "$tmp/truncated.json" \
  "bench_zero_shot: --oracle-cache $tmp/truncated.json: not JSON: "
[ "$(cat "$tmp/truncated.json")" = '{"k": ' ] || fail "truncated: the file changed"
printf '{"k": true}' >"$tmp/flag.json"
expect not_rewards "$tmp/flag.json" "bench_zero_shot: --oracle-cache $tmp/flag.json: not an object of rewards"
expect missing_folder "$tmp/nope/oracles.json" \
  "bench_zero_shot: --oracle-cache $tmp/nope/oracles.json: folder $tmp/nope does not exist"

# A set of one generated one-UAV scenario.
set_dir=$tmp/set
mkdir "$set_dir"
"$build/bin/rlpos-sim" generate --seed 7 --style open --out "$set_dir/open-1uav-s7.json" || fail generate
printf 'file\tseed\tstyle\tuavs\tues\nopen-1uav-s7.json\t7\topen\t1\t0\n' >"$set_dir/index.tsv"
cache=$tmp/oracles.json
run() {
  bench --build "$build" --policy "$repo/policies/generalist-1uav" --scenarios "$set_dir" \
    --jobs 1 --oracle-cache "$cache" >"$tmp/out" 2>"$tmp/err" || fail "run $1: $(cat "$tmp/err")"
}
row() { grep '^| open-1uav-s7.json' "$tmp/out"; }

run first
[ "$("$py" -c 'import json,sys; print(len(json.load(open(sys.argv[1]))))' "$cache")" = 1 ] ||
  fail "first: the cache does not hold one reward"
row | grep -q ' cached |$' && fail "first: a new search shown as cached: $(row)"
# A reward no search gives: the second run must take it from the cache.
"$py" -c 'import json,sys; c=json.load(open(sys.argv[1])); c={k: 0.5 for k in c}; json.dump(c, open(sys.argv[1], "w"))' "$cache"
run second
row | grep -q '| 0.5000 |.* cached |$' || fail "second: the cached reward not used: $(row)"
# Other bytes under the same name: another key, searched again.
"$build/bin/rlpos-sim" generate --seed 8 --style open --out "$set_dir/open-1uav-s7.json" || fail generate
run third
row | grep -q ' cached |$' && fail "third: a changed scenario taken from the cache: $(row)"
[ "$("$py" -c 'import json,sys; print(len(json.load(open(sys.argv[1]))))' "$cache")" = 2 ] ||
  fail "third: the new reward is not cached beside the first"

[ "$failures" -eq 0 ] && echo "bench_zero_shot --oracle-cache: 3 bad caches refused; written, read, missed"
exit $((failures > 0))
