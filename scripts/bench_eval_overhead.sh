#!/usr/bin/env bash
# Framework overhead of `rlpos-sim eval` against a plain ns-3 program of the same setup
# (tests/bench/bare_ns3_eval.cc), run side by side, alternating, on scenarios A and B; and
# the wall time per simulated second. Prints figures only; asserts nothing.
#   scripts/bench_eval_overhead.sh [BUILD_DIR] [REPEATS]
#   scripts/bench_eval_overhead.sh --instructions [BUILD_DIR]
# --instructions counts instructions under valgrind (callgrind) on shorter runs instead of wall
# time: repeatable to the instruction whatever else the machine is doing.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
instructions=0
if [ "${1:-}" = "--instructions" ]; then instructions=1; shift; fi
bin=${1:-"$here/build"}/bin
repeats=${2:-3}
for tool in rlpos-sim rlpos-bare-ns3; do
  [ -x "$bin/$tool" ] || { echo "bench: $bin/$tool not built (run scripts/bootstrap --tests)" >&2; exit 1; }
done

. "$here/scripts/lib/bench_timing.sh"  # wall, median

if [ "$instructions" -eq 1 ]; then
  command -v valgrind >/dev/null || { echo "bench: valgrind is not installed" >&2; exit 1; }
  irs() {  # prints the instruction count of "$@"
    local out
    out=$(mktemp)
    valgrind --tool=callgrind --callgrind-out-file="$out" "$@" >/dev/null 2>&1
    awk '/^summary:/ {print $2}' "$out"
    rm -f "$out"
  }
  printf '%-9s %-14s %6s %16s %16s %9s\n' scenario position sim_s bare_instr rlpos_instr overhead
  for case in "a 50,50,10 0.5" "b 50,35,10 1" "b 50,50,25 1"; do
    read -r name position duration <<<"$case"
    scenario="$here/campaigns/scenarios/$name.json"
    IFS=, read -r x y z <<<"$position"
    b=$(irs "$bin/rlpos-bare-ns3" "$scenario" "$x" "$y" "$z" "$duration")
    o=$(irs "$bin/rlpos-sim" eval --scenario "$scenario" --position "$position" \
      --duration "$duration" --set simulation.warmup=0.25 --no-progress)
    printf '%-9s %-14s %6s %16s %16s %8.2f%%\n' "$name" "$position" "$duration" "$b" "$o" \
      "$(echo "($o / $b - 1) * 100" | bc -l)"
  done
  exit 0
fi

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
