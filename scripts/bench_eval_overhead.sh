#!/usr/bin/env bash
# Framework overhead of `rlpos-sim eval` against a plain ns-3 program of the same setup
# (tests/bench/bare_ns3_eval.cc), run side by side, alternating, on scenarios A and B; and
# the wall time per simulated second. Prints figures only; asserts nothing.
#   scripts/bench_eval_overhead.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$here/build"}/bin
repeats=${2:-3}
for tool in rlpos-sim rlpos-bare-ns3; do
  [ -x "$bin/$tool" ] || { echo "bench: $bin/$tool not built (run scripts/bootstrap)" >&2; exit 1; }
done

wall() {  # prints the wall seconds of "$@" (output discarded)
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

printf '%-9s %-14s %6s %12s %12s %9s %14s\n' scenario position sim_s bare_wall_s rlpos_wall_s overhead rlpos_wall/sim_s
for case in "a 50,50,10 3" "b 50,35,10 5" "b 50,50,25 5"; do
  read -r name position duration <<<"$case"
  scenario="$here/campaigns/scenarios/$name.json"
  IFS=, read -r x y z <<<"$position"
  bare=() ours=()
  for _ in $(seq "$repeats"); do
    bare+=("$(wall "$bin/rlpos-bare-ns3" "$scenario" "$x" "$y" "$z" "$duration")")
    ours+=("$(wall "$bin/rlpos-sim" eval --scenario "$scenario" --position "$position" \
      --duration "$duration" --no-progress)")
  done
  b=$(printf '%s\n' "${bare[@]}" | median)
  o=$(printf '%s\n' "${ours[@]}" | median)
  # Both simulate duration + 0.5 s of drain.
  printf '%-9s %-14s %6s %12.2f %12.2f %8.1f%% %14.2f\n' "$name" "$position" "$duration" "$b" "$o" \
    "$(echo "($o / $b - 1) * 100" | bc -l)" "$(echo "$o / ($duration + 0.5)" | bc -l)"
done
