#!/usr/bin/env bash
# The generality benchmark, reduced: scripts/bench_generality.py on scenarios B (one UAV) and
# campus2 (two), train seed 1, dqn, ppo and sac with 3 short training episodes. It runs through
# the campaign runner, and the optimality section must show one run per algorithm and UAV
# count, each rl reward a share of the oracle's in (0, 1.05] (1.05: sac's continuous moves may
# land off the oracle's grid, and with two UAVs the oracle is a coordinate descent). Then its
# zero-shot mode: a tiny policy for any scenario (one UAV) beside centroid, with no training;
# campus2 (two UAVs) is left out, and said so.
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
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["label"].startswith("rl")]
got = sorted((r["scenario"], r["uavs"], r["algorithm"], r["train_seed"]) for r in rows)
want = sorted((s, u, a, "1") for s, u in (("B", "1"), ("campus2", "2")) for a in ("dqn", "ppo", "sac"))
assert got == want, got
for r in rows:
    ratio = float(r["ratio"])
    assert abs(ratio - float(r["rl_reward"]) / float(r["oracle_reward"])) < 1e-9, r
    assert 0 < ratio <= 1.05, r
PY
grep -q "^## Optimality: each placement against the oracle" "$REPORT/summary.md" || fail "summary.md has no optimality section"
if python3 -c 'import matplotlib' 2>/dev/null; then
  [ -s "$REPORT/optimality_cdf.png" ] || fail "no optimality_cdf.png"
fi

# Zero-shot: a tiny policy trained on generated scenarios (neither B nor campus2).
"$BIN/rlpos-sim" train --generated open --steps 240 --seed 3 --validation-scenarios 2 \
  --set agent.ppo.num_envs=4 --set agent.train_episode_steps=10 --set agent.ppo.rollout_steps=10 \
  --set agent.hidden=[16] --set env.coverage_map=4 --set env.observed_ues=4 --set env.height_map=3 \
  --out "$WORK/tiny" >"$WORK/tiny.log" 2>&1 || fail "training across scenarios: $(tail -n 3 "$WORK/tiny.log")"
python3 "$SRC/scripts/bench_generality.py" --scenarios "$WORK/scenarios" --algorithms none \
  --policy "$WORK/tiny" --workers 2 --build "$BIN/.." --db "$DB" \
  --tag "$TAG" --name zero-shot >"$WORK/zs.txt" 2>"$WORK/zs_err.txt" ||
  { rc=$?; cat "$WORK/zs.txt" "$WORK/zs_err.txt" >&2; fail "zero-shot bench_generality exited $rc"; }
grep -q "left out campus2.json (2 UAV(s))" "$WORK/zs_err.txt" || fail "campus2 not said left out: $(cat "$WORK/zs_err.txt")"
ZS=$(sed -n 's/^campaign \([0-9a-f]*\) .*/\1/p' "$WORK/zs.txt")
[ -n "$ZS" ] && [ "$ZS" != "$ID" ] || fail "zero-shot printed no campaign id of its own: $(cat "$WORK/zs.txt")"
# B only: oracle, centroid and the policy's position, one eval each.
expect_eq "zero-shot jobs" "$(sql "$DB" "SELECT COUNT(*) FROM jobs WHERE campaign_id = '$ZS' AND state = 'succeeded'")" 6
for who in rl+tiny centroid oracle; do
  grep -Eq "^${who//+/\\+} +1 +1 +1 +[0-9.]+ +[0-9.]+ +[0-9.]+ +[01]/1 \([0-9]+ %\) +[0-9.]+$" "$WORK/zs.txt" ||
    fail "no zero-shot row for $who with its placement seconds: $(cat "$WORK/zs.txt")"
done
python3 - "$WORK/reports/$ZS/optimality.csv" "$DB" "$ZS" <<'PY' || fail "zero-shot optimality.csv: $(cat "$WORK/reports/$ZS/optimality.csv")"
import csv, sqlite3, sys
rows = {r["label"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert sorted(rows) == ["centroid", "oracle", "rl+tiny"], sorted(rows)
db = sqlite3.connect(sys.argv[2])
for label, r in rows.items():
    # The placement's seconds are its position job's, as the store recorded them (a job the
    # cache served: its source's).
    (want,) = db.execute(
        "SELECT COALESCE(s.finished_at - s.started_at, j.finished_at - j.started_at) FROM jobs j "
        "LEFT JOIN jobs s ON s.id = j.cached_from WHERE j.campaign_id = ? AND "
        "j.kind = 'position' AND j.label = ?", (sys.argv[3], label)).fetchone()
    assert abs(float(r["placement_s"]) - want) < 1e-6, (label, r["placement_s"], want)
    assert abs(float(r["ratio"]) - float(r["rl_reward"]) / float(r["oracle_reward"])) < 1e-9, r
assert float(rows["oracle"]["ratio"]) == 1.0
PY
echo "ok: generality smoke test $ID: rl against the oracle for dqn, ppo, sac on 1 and 2 UAVs; zero-shot $ZS"
