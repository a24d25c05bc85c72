#!/usr/bin/env bash
# The packet level with tcmalloc (what rlpos-sim links) against glibc's malloc (its twin,
# scripts/lib/glibc_malloc_twin), side by side: the CPU seconds (user + system) of each run,
# alternating which goes first, and whether both printed the same bytes. Cases: scenarios A, B
# and C at the baseline (eval, their own duration), urban3 (three UAVs) and a packet-level track
# run on the street of campaigns/mobility.json. Prints figures only; asserts nothing.
#   scripts/bench_tcmalloc.sh [BUILD_DIR] [PAIRS] [CASES]   (CASES: e.g. "A,urban3"; default all)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$here/build"}
pairs=${2:-4}
only=${3:-}
sim=$build/bin/rlpos-sim
[ -x "$sim" ] || { echo "bench: $sim not built (run scripts/bootstrap)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$here/scripts/lib/glibc_malloc_twin" "$build/bin" "$work/twin"
twin=$work/twin/bin/rlpos-sim
. "$here/scripts/lib/bench_timing.sh"  # cpu_seconds, median
eval_args() {  # eval_args SCENARIO: eval at the baseline, RngRun 1, as JSON
  echo "eval --scenario $1 $("$here/scripts/lib/baseline_flags" "$sim" "$1") --RngRun 1 --json"
}

scenarios=$here/campaigns/scenarios
cases=(
  "A|$(eval_args "$scenarios/a.json")"
  "B|$(eval_args "$scenarios/b.json")"
  "C|$(eval_args "$scenarios/c.json")"
  "urban3|$(eval_args "$scenarios/urban3.json")"
  "track|track --scenario $scenarios/mobility-street.json --positioner centroid-track --duration 10 --RngRun 1 --set env.decision_interval=1 --fidelity packet --json"
)
span() {  # span FILE FORMAT: "median [min-max]" of the numbers in FILE
  printf "$2 [$2-$2]" "$(median <"$1")" "$(sort -g "$1" | head -1)" "$(sort -g "$1" | tail -1)"
}
echo "rlpos-sim (tcmalloc) against its glibc-malloc twin; $pairs pairs; CPU seconds, median [min-max]"
printf '%-13s %18s %18s %20s %s\n' case "glibc malloc" tcmalloc "ratio tcmalloc/glibc" "same output"
for c in "${cases[@]}"; do
  name=${c%%|*}
  [ -z "$only" ] || [[ ",$only," == *",$name,"* ]] || continue
  read -r -a args <<<"${c#*|}"
  : >"$work/glibc" ; : >"$work/tc" ; : >"$work/ratio"
  same=yes
  for ((i = 0; i < pairs; i++)); do
    if ((i % 2 == 0)); then
      g=$(cpu_seconds "$work/g.out" "$twin" "${args[@]}"); t=$(cpu_seconds "$work/t.out" "$sim" "${args[@]}")
    else
      t=$(cpu_seconds "$work/t.out" "$sim" "${args[@]}"); g=$(cpu_seconds "$work/g.out" "$twin" "${args[@]}")
    fi
    cmp -s "$work/g.out" "$work/t.out" || same=no
    echo "$g" >>"$work/glibc"; echo "$t" >>"$work/tc"; echo "$t / $g" | bc -l >>"$work/ratio"
  done
  printf '%-13s %18s %18s %20s %s\n' "$name" "$(span "$work/glibc" %.1f)" "$(span "$work/tc" %.1f)" \
    "$(span "$work/ratio" %.2f)" "$same"
done
