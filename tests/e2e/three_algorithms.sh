#!/usr/bin/env bash
# A campaign of three algorithms: each trains its own policy in its own job (sac on the
# continuous action space), each policy's position is evaluated under its own label, and the
# report shows the three.
source "$(dirname "$0")/lib.sh"
DB=$WORK/rlpos.db
run_campaign "$SRC/tests/e2e/campaigns/three_algorithms.json"

# 1 oracle position + 3 trains + 4 evals.
expect_complete "$DB" 8
expect_eq "train jobs" "$(sql "$DB" "SELECT group_concat(key, ' ') FROM (SELECT key FROM jobs
  WHERE kind = 'train' ORDER BY key)" | sed "s|$ID/||g")" \
  "train/B/dqn/seed1 train/B/ppo/seed1 train/B/sac/seed1"
expect_eq "eval labels" "$(sql "$DB" "SELECT group_concat(positioner, ' ') FROM (SELECT
  positioner FROM v_eval_runs ORDER BY positioner)")" "oracle rl@dqn rl@ppo rl@sac"
# Each train job trained the algorithm its label says (the result it returned records it).
for alg in dqn ppo sac; do
  trained=$(sql "$DB" "SELECT json_extract(result_json, '$.algorithm') FROM jobs
    WHERE key LIKE '%train/B/$alg/seed1'")
  expect_eq "algorithm of train/B/$alg" "$trained" "$alg"
done

REPORT=$WORK/reports/$ID
for alg in dqn ppo sac; do
  grep -q "| B | rl@$alg |" "$REPORT/summary.md" || fail "summary.md has no rl@$alg row: $(cat "$REPORT/summary.md")"
  grep -q "^B,rl@$alg," "$REPORT/learning_curves.csv" || fail "learning_curves.csv has no rl@$alg curve"
  grep -q "^B  *rl@$alg " "$WORK/out.txt" || fail "the printed summary has no rl@$alg row"
done
echo "ok: three-algorithm campaign $ID; the report shows rl@dqn, rl@ppo and rl@sac"
