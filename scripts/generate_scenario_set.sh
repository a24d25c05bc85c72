#!/usr/bin/env bash
# Writes a named set of generated scenarios: "train", the larger one-UAV "tune" and "tune-many"
# (two to six UAVs) to tune on, "heldout" to report on, "train-many" and "heldout-many" the same
# with four to six UAVs, "fresh" (one UAV) and "fresh-many" (two to six), held out from
# everything else, kept for checking a choice after it is made, "confirm" and "confirm-many",
# larger, for the next such check once the fresh sets have been looked at, "audit" and
# "audit-many", the same size, for the check after that, "verify" and "verify-many" for the one
# after audit, "check" and "check-many" for the one after verify, "vet" and "vet-many" for the
# one after check, "trial" and "trial-many" for the one after vet, "probe" and "probe-many" for
# the one after trial, "gauge" and "gauge-many" for the one after probe, and "assay" and
# "assay-many" for the one after gauge. Each scenario is written by rlpos-sim generate and
# checked by rlpos-sim validate; the set appears whole (written beside DIR, then renamed) or not
# at all.
#   scripts/generate_scenario_set.sh --out DIR [--build BUILD_DIR] --set train|tune|tune-many|
#     heldout|train-many|heldout-many|fresh|fresh-many|confirm|confirm-many|audit|audit-many|
#     verify|verify-many|check|check-many|vet|vet-many|trial|trial-many|probe|probe-many|
#     gauge|gauge-many|assay|assay-many
#   scripts/generate_scenario_set.sh --set S --list   # the set's file, seed, style and UAVs only
# Seeds are fixed and the sets' ranges are disjoint (docs/scenarios.md, Generated scenarios):
#   seed = base + 1000 * uavs + 100 * style + i, i = 0, 1, ...
#   base: train 10000, tune and tune-many 20000, verify and verify-many 30000, audit and
#   audit-many 40000, check and check-many 50000, confirm and confirm-many 60000, fresh and
#   fresh-many 70000, vet and vet-many 80000, heldout 90000, trial and trial-many 100000, probe and
#   probe-many 110000, gauge and gauge-many 120000, assay and assay-many 130000; style: urban 0,
#   campus 1, suburb 2, open 3.
# Scenarios per style and UAV count: train and heldout 8, 2, 2 for 1, 2, 3 UAVs (48 each);
# train-many and heldout-many 2, 2, 2 for 4, 5, 6 UAVs (24 each); fresh 16 with one UAV (64);
# fresh-many 2 each for 2 to 6 UAVs (40); tune, confirm, audit, verify, check, vet, trial,
# probe, gauge and assay 32 with one UAV (128); tune-many, confirm-many, audit-many, verify-many,
# check-many, vet-many, trial-many, probe-many, gauge-many and assay-many 4 each for 2 to 6 UAVs
# (80).
# DIR/index.tsv lists file, seed, style, UAVs and UEs.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
set_name="" out="" build="$here/build" list=0
# The pairs of one shape: NAME, 32 one-UAV scenarios per style, and NAME-many, 4 per style for each
# of 2 to 6 UAVs, on the pair's seed base (tune's to tune on, the others' to check choices).
check_pairs=(confirm audit verify check vet trial probe gauge assay)
declare -A pair_base=([tune]=20000 [verify]=30000 [audit]=40000 [check]=50000 [confirm]=60000
  [vet]=80000 [trial]=100000 [probe]=110000 [gauge]=120000
  [assay]=130000)
set_names="train|tune|tune-many|heldout|train-many|heldout-many|fresh|fresh-many"
for pair in "${check_pairs[@]}"; do set_names+="|$pair|$pair-many"; done
usage() { echo "usage: $0 --set $set_names --out DIR [--build BUILD_DIR] | --list" >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --set) set_name=${2:-}; shift 2 || usage ;;
    --out) out=${2:-}; shift 2 || usage ;;
    --build) build=${2:-}; shift 2 || usage ;;
    --list) list=1; shift ;;
    *) usage ;;
  esac
done
# counts[k]: scenarios per style with first_uavs + k UAVs.
case "$set_name" in
  train) base=10000; first_uavs=1; counts=(8 2 2) ;;
  heldout) base=90000; first_uavs=1; counts=(8 2 2) ;;
  train-many) base=10000; first_uavs=4; counts=(2 2 2) ;;
  heldout-many) base=90000; first_uavs=4; counts=(2 2 2) ;;
  fresh) base=70000; first_uavs=1; counts=(16) ;;
  fresh-many) base=70000; first_uavs=2; counts=(2 2 2 2 2) ;;
  *)
    pair=${set_name%-many}
    if [ -z "$pair" ] || [ -z "${pair_base[$pair]:-}" ]; then
      echo "generate_scenario_set: --set must be one of ${set_names//|/, }" >&2
      exit 2
    fi
    base=${pair_base[$pair]}
    if [ "$pair" = "$set_name" ]; then
      first_uavs=1; counts=(32)
    else
      first_uavs=2; counts=(4 4 4 4 4)
    fi ;;
esac
styles=(urban campus suburb open)
# Each scenario of the set: file, seed, style and UAVs, tab-separated.
each_scenario() {
  local k s i uavs seed
  for ((k = 0; k < ${#counts[@]}; k++)); do
    uavs=$((first_uavs + k))
    for s in 0 1 2 3; do
      for ((i = 0; i < counts[k]; i++)); do
        seed=$((base + 1000 * uavs + 100 * s + i))
        printf '%s\t%s\t%s\t%s\n' "${styles[s]}-${uavs}uav-s$seed.json" "$seed" "${styles[s]}" "$uavs"
      done
    done
  done
}
if [ "$list" = 1 ]; then
  [ -z "$out" ] || usage
  printf 'file\tseed\tstyle\tuavs\n'
  each_scenario
  exit 0
fi
[ -n "$out" ] || usage
sim="$build/bin/rlpos-sim"
[ -x "$sim" ] || { echo "generate_scenario_set: $sim not built (run scripts/bootstrap)" >&2; exit 1; }
if [ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null || echo file)" ]; then
  echo "generate_scenario_set: $out exists and is not an empty folder" >&2
  exit 2
fi
mkdir -p "$(dirname "$out")"
work=$(mktemp -d "$(dirname "$out")/.$(basename "$out").XXXXXX")
trap 'rm -rf "$work"' EXIT

printf 'file\tseed\tstyle\tuavs\tues\n' > "$work/index.tsv"
# The loop reads the listing on stdin: the commands in it read nothing.
while IFS=$'\t' read -r file seed style uavs; do
  "$sim" generate --seed "$seed" --style "$style" --uavs "$uavs" --out "$work/$file" < /dev/null
  "$sim" validate "$work/$file" > /dev/null < /dev/null
  ues=$(/usr/bin/python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["ues"]))' \
    "$work/$file" < /dev/null)
  printf '%s\t%s\t%s\t%s\t%s\n' "$file" "$seed" "$style" "$uavs" "$ues" >> "$work/index.tsv"
done < <(each_scenario)
rmdir "$out" 2>/dev/null || true
mv "$work" "$out"
chmod 755 "$out"
trap - EXIT
echo "$set_name: $(($(wc -l < "$out/index.tsv") - 1)) scenarios in $out"
