#!/usr/bin/env bash
# Training speed of a policy for any scenario (`rlpos-sim train --generated`) with two builds,
# side by side, alternating: one UAV, and two to six UAVs (whose coverage maps are worked out
# again after every move of another UAV). Prints wall seconds, env steps per second, the ratio,
# and whether both builds trained the same policy (policy.pt bytes). Asserts nothing.
#   scripts/bench_generalist_train.sh BUILD_A BUILD_B [STEPS] [REPEATS]
# For example, against the build of an older commit:
#   git worktree add /tmp/old OLD && cmake -S /tmp/old -B /tmp/old/build -G Ninja &&
#   ninja -C /tmp/old/build bin/rlpos-sim && scripts/bench_generalist_train.sh /tmp/old/build build
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,9p' "$0" >&2; exit 2; }
here=$(cd "$(dirname "$0")/.." && pwd)
steps=${3:-6400}
repeats=${4:-1}
for build in "$1" "$2"; do
  [ -x "$build/bin/rlpos-sim" ] || { echo "bench: $build/bin/rlpos-sim not built" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/scripts/lib/bench_timing.sh"  # wall, median

train() {  # train BUILD UAVS OUT
  rm -rf "$3" "$3.partial"
  "$1/bin/rlpos-sim" train --generated urban,campus,suburb,open --uavs "$2" --steps "$steps" \
    --seed 1 --validation-scenarios 2 --out "$3" 2>/dev/null
}

echo "env steps: $steps per training, validation on 2 scenarios; $(nproc) cores; median of $repeats"
printf '%-6s %10s %10s %10s %10s %8s %s\n' uavs "A s" "A steps/s" "B s" "B steps/s" "B / A" \
  "same policy"
for uavs in 1 2-6; do
  a_times=() b_times=()
  for ((r = 0; r < repeats; ++r)); do
    a_times+=("$(wall train "$1" "$uavs" "$work/a")")
    b_times+=("$(wall train "$2" "$uavs" "$work/b")")
  done
  a=$(printf '%s\n' "${a_times[@]}" | median)
  b=$(printf '%s\n' "${b_times[@]}" | median)
  same=no
  cmp -s "$work/a/policy.pt" "$work/b/policy.pt" && same=yes
  printf '%-6s %10.1f %10.1f %10.1f %10.1f %8.3f %s\n' "$uavs" "$a" "$(echo "$steps / $a" | bc -l)" \
    "$b" "$(echo "$steps / $b" | bc -l)" "$(echo "$b / $a" | bc -l)" "$same"
done
