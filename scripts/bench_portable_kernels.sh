#!/usr/bin/env bash
# What the portable kernels cost: training with them (rlpos-sim's default: libtorch's baseline
# kernels, OpenBLAS' Prescott) against the CPU's own (RLPOS_NATIVE_KERNELS=1), side by side,
# alternating, one training at a time. CPU seconds (user + system) are the figure to read on a
# shared machine; wall seconds are printed too. Also says whether both trained the same policy
# bytes (on this CPU they may differ: that is what the pin is for). Prints figures only.
#   scripts/bench_portable_kernels.sh [BUILD_DIR] [REPEATS]
# Cases: dqn, ppo and sac on scenario B (seed 1, each algorithm's default budget), and dqn on a
# generated campus with three UAVs (training-set seed 13100).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
sim=${1:-"$here/build"}/bin/rlpos-sim
repeats=${2:-2}
[ -x "$sim" ] || { echo "bench: $sim not built (run scripts/bootstrap)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/scripts/lib/bench_timing.sh"  # median
"$sim" generate --seed 13100 --style campus --uavs 3 --out "$work/campus-3uav.json" >/dev/null

train() {  # train SCENARIO ALGORITHM OUT NATIVE: one training; prints "cpu_s wall_s"
  rm -rf "$3"
  local start end
  start=$(date +%s.%N)
  TIMEFORMAT='%U %S'
  local times
  times=$( { time env ${4:+RLPOS_NATIVE_KERNELS=1} "$sim" train --scenario "$1" \
    --fidelity analytic --algorithm "$2" --seed 1 --out "$3" >/dev/null 2>"$3.log"; } 2>&1) ||
    { echo "bench: training failed: $(tail -1 "$3.log")" >&2; return 1; }
  end=$(date +%s.%N)
  read -r user sys <<<"$times"
  echo "$(echo "$user + $sys" | bc -l) $(echo "$end - $start" | bc -l)"
}

echo "$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
echo "repeats: $repeats; median seconds per training"
printf '%-12s %-4s %9s %9s %6s %9s %9s %s\n' scenario alg "cpu pin" "cpu own" ratio \
  "wall pin" "wall own" "same policy.pt"
for case in "b dqn" "b ppo" "b sac" "campus-3uav dqn"; do
  read -r scenario alg <<<"$case"
  file=$here/campaigns/scenarios/$scenario.json
  [ "$scenario" = b ] || file=$work/$scenario.json
  : >"$work/pin.t"
  : >"$work/own.t"
  for _ in $(seq "$repeats"); do
    train "$file" "$alg" "$work/pin" "" >>"$work/pin.t"
    train "$file" "$alg" "$work/own" 1 >>"$work/own.t"
  done
  cpu_pin=$(cut -d' ' -f1 "$work/pin.t" | median)
  cpu_own=$(cut -d' ' -f1 "$work/own.t" | median)
  wall_pin=$(cut -d' ' -f2 "$work/pin.t" | median)
  wall_own=$(cut -d' ' -f2 "$work/own.t" | median)
  same=no
  cmp -s "$work/pin/policy.pt" "$work/own/policy.pt" && same=yes
  printf '%-12s %-4s %9.1f %9.1f %6.2f %9.1f %9.1f %s\n' "$scenario" "$alg" "$cpu_pin" "$cpu_own" \
    "$(echo "$cpu_pin / $cpu_own" | bc -l)" "$wall_pin" "$wall_own" "$same"
done
