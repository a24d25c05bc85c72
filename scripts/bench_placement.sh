#!/usr/bin/env bash
# Time per placement of a policy (`rlpos-sim position --positioner rl --policy`: the process, the
# policy's load and its greedy flight) with two builds, side by side, alternating, over every
# scenario of a folder. Prints each scenario's seconds with both builds and their ratio, then the
# medians and the worst, and whether both builds placed the UAVs at the same spot (the printed
# placement). Asserts nothing.
#   scripts/bench_placement.sh BUILD_A BUILD_B POLICY SCENARIO_DIR [REPEATS]
# For example (heldout-many: scripts/generate_scenario_set.sh --set heldout-many --out DIR):
#   scripts/bench_placement.sh /tmp/old/build build policies/generalist-multi heldout-many
set -euo pipefail
[ $# -ge 4 ] || { sed -n '2,9p' "$0" >&2; exit 2; }
here=$(cd "$(dirname "$0")/.." && pwd)
policy=$3
dir=$4
repeats=${5:-1}
for build in "$1" "$2"; do
  [ -x "$build/bin/rlpos-sim" ] || { echo "bench: $build/bin/rlpos-sim not built" >&2; exit 1; }
done
[ -d "$dir" ] || { echo "bench: no scenario folder $dir" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/scripts/lib/bench_timing.sh"  # wall, median

place() {  # place BUILD SCENARIO OUT
  "$1/bin/rlpos-sim" position --scenario "$2" --positioner rl --policy "$policy" >"$3"
}

echo "policy $policy; $(nproc) cores; median of $repeats per scenario and build"
printf '%-28s %8s %8s %8s %s\n' scenario "A s" "B s" "B / A" "same placement"
: >"$work/rows"
for scenario in "$dir"/*.json; do
  a_times=() b_times=()
  for ((r = 0; r < repeats; ++r)); do
    a_times+=("$(wall place "$1" "$scenario" "$work/a.txt")")
    b_times+=("$(wall place "$2" "$scenario" "$work/b.txt")")
  done
  a=$(printf '%s\n' "${a_times[@]}" | median)
  b=$(printf '%s\n' "${b_times[@]}" | median)
  same=no
  cmp -s "$work/a.txt" "$work/b.txt" && same=yes
  ratio=$(echo "$b / $a" | bc -l)
  printf '%-28s %8.2f %8.2f %8.3f %s\n' "$(basename "$scenario" .json)" "$a" "$b" "$ratio" "$same"
  echo "$a $b $ratio $same" >>"$work/rows"
done
printf '%-28s %8.2f %8.2f %8.3f\n' median "$(cut -d' ' -f1 "$work/rows" | median)" \
  "$(cut -d' ' -f2 "$work/rows" | median)" "$(cut -d' ' -f3 "$work/rows" | median)"
printf '%-28s %8.2f %8.2f %8.3f\n' worst "$(cut -d' ' -f1 "$work/rows" | sort -g | tail -1)" \
  "$(cut -d' ' -f2 "$work/rows" | sort -g | tail -1)" "$(cut -d' ' -f3 "$work/rows" | sort -g | tail -1)"
echo "same placement in $(grep -c ' yes$' "$work/rows") of $(wc -l <"$work/rows")"
