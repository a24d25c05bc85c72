#!/usr/bin/env bash
# Training wall time with libtorch on one thread (rlpos-sim's default) against libtorch's own
# default of one thread per core (OMP_NUM_THREADS=$(nproc)), side by side, alternating; one
# training at a time, then two at once as on a worker with two slots. Also says whether both
# settings trained the same policy (same reward and position). Prints figures only; asserts
# nothing.
#   scripts/bench_train_threads.sh [BUILD_DIR] [REPEATS]
# Cases: dqn, ppo and sac on a generated urban scenario with one UAV (training-set seed 11002),
# and dqn on a campus with three (13100).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
sim=${1:-"$here/build"}/bin/rlpos-sim
repeats=${2:-2}
[ -x "$sim" ] || { echo "bench: $sim not built (run scripts/bootstrap)" >&2; exit 1; }
cores=$(nproc)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/scripts/lib/bench_timing.sh"  # wall, median
"$sim" generate --seed 11002 --style urban --uavs 1 --out "$work/urban-1uav.json"
"$sim" generate --seed 13100 --style campus --uavs 3 --out "$work/campus-3uav.json"

train() {  # train SCENARIO ALGORITHM OUT [THREADS]: one training; THREADS empty = our default
  local threads=${4:-}
  rm -rf "$3"
  env ${threads:+OMP_NUM_THREADS=$threads} "$sim" train --scenario "$1" --fidelity analytic \
    --algorithm "$2" --seed 1 --out "$3" >/dev/null 2>"$3.log" ||
    { echo "bench: training failed: $(tail -1 "$3.log")" >&2; return 1; }
}
pair() {  # pair SCENARIO ALGORITHM THREADS: two trainings at once
  train "$1" "$2" "$work/pa" "$3" &
  train "$1" "$2" "$work/pb" "$3" &
  wait
}
outcome() { /usr/bin/python3 -c 'import json, sys; r = json.load(open(sys.argv[1])); print(r["reward"], r["positions"])' "$1"; }

echo "cores: $cores; repeats: $repeats; median wall seconds"
printf '%-12s %-5s %9s %9s %6s %10s %10s %6s %s\n' scenario alg "1 thread" "$cores thr" ratio \
  "pair 1thr" "pair ${cores}thr" ratio "same policy"
for case in "urban-1uav dqn" "urban-1uav ppo" "urban-1uav sac" "campus-3uav dqn"; do
  read -r scenario alg <<<"$case"
  one=() many=() pone=() pmany=()
  for ((r = 0; r < repeats; r++)); do
    one+=("$(wall train "$work/$scenario.json" "$alg" "$work/one")")
    many+=("$(wall train "$work/$scenario.json" "$alg" "$work/many" "$cores")")
    pone+=("$(wall pair "$work/$scenario.json" "$alg" "")")
    pmany+=("$(wall pair "$work/$scenario.json" "$alg" "$cores")")
  done
  a=$(printf '%s\n' "${one[@]}" | median) b=$(printf '%s\n' "${many[@]}" | median)
  c=$(printf '%s\n' "${pone[@]}" | median) d=$(printf '%s\n' "${pmany[@]}" | median)
  same=no
  [ "$(outcome "$work/one/result.json")" = "$(outcome "$work/many/result.json")" ] && same=yes
  printf '%-12s %-5s %9.1f %9.1f %6.2f %10.1f %10.1f %6.2f %s\n' "$scenario" "$alg" "$a" "$b" \
    "$(echo "$b / $a" | bc -l)" "$c" "$d" "$(echo "$d / $c" | bc -l)" "$same"
done
echo "ratio: libtorch's default over one thread (above 1: one thread is faster)"
