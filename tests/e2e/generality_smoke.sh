#!/usr/bin/env bash
# The generality benchmark, reduced: scripts/bench_generality.py on scenarios B (one UAV) and
# campus2 (two), train seed 1, dqn, ppo and sac with 3 short training episodes. It runs through
# the campaign runner, and the optimality section must show one run per algorithm and UAV
# count, each rl reward a share of the oracle's in (0, 1.05] (1.05: sac's continuous moves may
# land off the oracle's grid, and with two UAVs the oracle is a coordinate descent).
source "$(dirname "$0")/lib.sh"
DB=$WORK/rlpos.db
mkdir "$WORK/scenarios"
cp "$SRC/campaigns/scenarios/b.json" "$SRC/campaigns/scenarios/campus2.json" "$WORK/scenarios/"
python3 "$SRC/scripts/bench_generality.py" --scenarios "$WORK/scenarios" --seeds 1 \
  --episodes 3 --set env.episode_duration=30 --workers 2 --build "$BIN/.." --db "$DB" \
  --tag "$TAG" >"$WORK/out.txt" 2>"$WORK/err.txt" ||
  { rc=$?; cat "$WORK/out.txt" "$WORK/err.txt" >&2; fail "bench_generality exited $rc"; }
ID=$(sed -n 's/^campaign \([0-9a-f]*\) .*/\1/p' "$WORK/out.txt")
[ -n "$ID" ] || fail "bench_generality printed no campaign id: $(cat "$WORK/out.txt")"

# 2 oracle positions + 6 trains + 8 evals, each eval with its reward.
expect_complete "$DB" 16
expect_eq "evals without a reward" "$(sql "$DB" "SELECT COUNT(*) FROM metrics WHERE reward IS NULL")" 0

# The printed table: one row per algorithm and UAV count, one run each.
for alg in dqn ppo sac; do
  for uavs in 1 2; do
    grep -Eq "^$alg +$uavs +1 +1 +[0-9.]+ +[0-9.]+ +[0-9.]+ +[01]/1 " "$WORK/out.txt" ||
      fail "no optimality row for $alg with $uavs UAV(s): $(cat "$WORK/out.txt")"
  done
done

# Every run, in the report: the ratio is rl's reward over the oracle's, in (0, 1.05].
REPORT=$WORK/reports/$ID
python3 - "$REPORT/optimality.csv" <<'PY' || fail "optimality.csv: $(cat "$REPORT/optimality.csv")"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
got = sorted((r["scenario"], r["uavs"], r["algorithm"], r["train_seed"]) for r in rows)
want = sorted((s, u, a, "1") for s, u in (("B", "1"), ("campus2", "2")) for a in ("dqn", "ppo", "sac"))
assert got == want, got
for r in rows:
    ratio = float(r["ratio"])
    assert abs(ratio - float(r["rl_reward"]) / float(r["oracle_reward"])) < 1e-9, r
    assert 0 < ratio <= 1.05, r
PY
grep -q "^## Optimality: rl against the oracle" "$REPORT/summary.md" || fail "summary.md has no optimality section"
if python3 -c 'import matplotlib' 2>/dev/null; then
  [ -s "$REPORT/optimality_cdf.png" ] || fail "no optimality_cdf.png"
fi
echo "ok: generality smoke test $ID: rl against the oracle for dqn, ppo, sac on 1 and 2 UAVs"
