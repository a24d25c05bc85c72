#!/usr/bin/env bash
# Issue figures for the positioners: per scenario, trains the agent (analytic fidelity), asks
# every positioner for its position (nLoS and analytic reward), then evaluates each position at
# packet level (throughput, mean delay). Prints one table; asserts nothing.
#   scripts/compare_positioners.sh [BUILD_DIR] [EVAL_DURATION_S] [SEED] [SCENARIOS...]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
sim=${1:-"$here/build"}/bin/rlpos-sim
duration=${2:-5}
seed=${3:-1}
shift $(( $# > 3 ? 3 : $# ))
scenarios=("$@")
[ ${#scenarios[@]} -gt 0 ] || scenarios=(a b c)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

field() { python3 -c "import json,sys; d=json.load(open('$1')); print($2)"; }

printf '%-3s %-9s %-20s %5s %8s %10s %10s %9s\n' sc positioner position nLoS reward thr_Mbps delay_ms vs_base
for name in "${scenarios[@]}"; do
  scenario="$here/campaigns/scenarios/$name.json"
  "$sim" train --scenario "$scenario" --fidelity analytic --seed "$seed" --out "$work/$name-policy" \
    >/dev/null 2>&1
  base_thr=""
  for positioner in baseline rl oracle centroid; do
    extra=()
    [ "$positioner" = rl ] && extra=(--policy "$work/$name-policy")
    "$sim" position --scenario "$scenario" --positioner "$positioner" "${extra[@]}" --json \
      >"$work/pos.json"
    pos=$(field "$work/pos.json" "','.join('%g' % v for v in d['position'])")
    "$sim" eval --scenario "$scenario" --position "$pos" --duration "$duration" --run 1 --json \
      --no-progress >"$work/eval.json"
    thr=$(field "$work/eval.json" "d['aggregate_throughput_mbps']")
    [ -n "$base_thr" ] || base_thr=$thr
    printf '%-3s %-9s %-20s %5s %8.4f %10.2f %10.3f %8.1f%%\n' "$name" "$positioner" "($pos)" \
      "$(field "$work/pos.json" "'%d/%d' % (d['n_los'], d['n_ues'])")" \
      "$(field "$work/pos.json" "d['reward']")" "$thr" \
      "$(field "$work/eval.json" "d['mean_delay_ms'] if d['mean_delay_ms'] is not None else float('nan')")" \
      "$(python3 -c "print(($thr / $base_thr - 1) * 100)")"
  done
done
