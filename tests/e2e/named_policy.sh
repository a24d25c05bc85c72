#!/usr/bin/env bash
# A campaign whose rl positioner names a policy folder instead of training one: a tiny policy
# trained on B by `rlpos-sim train` is packed at submit, travels to the workers by its hash, is
# flown there by `position --positioner rl --policy`, and its evals (labelled rl+<folder>) sit at
# the placement `rlpos-sim position --policy` prints on this machine. Bad folders are refused at
# submit, --dry-run included, with one line and nothing run. A policy for any scenario enters a
# campaign on scenarios it never saw.
source "$(dirname "$0")/lib.sh"
SIM=$BIN/rlpos-sim
DB=$WORK/rlpos.db
B=$SRC/campaigns/scenarios/b.json

mkdir -p "$WORK/policies"
"$SIM" train --scenario "$B" --set env.episode_duration=30 --fidelity analytic --seed 1 \
  --episodes 3 --out "$WORK/policies/tiny" >"$WORK/train.log" 2>&1 \
  || fail "training failed: $(tail -n 3 "$WORK/train.log")"
"$SIM" position --positioner rl --policy "$WORK/policies/tiny" --scenario "$B" \
  --set env.episode_duration=30 --json >"$WORK/position.json" 2>"$WORK/position.log" \
  || fail "position failed: $(tail -n 3 "$WORK/position.log")"
at() { python3 -c 'import json,sys; p=json.load(open(sys.argv[1]))["position"]; print(",".join("%.3f" % v for v in p))' "$1"; }
expected=$(at "$WORK/position.json")
# A worker that flew anything but the policy would most likely stay at the baseline: the check
# below can tell only if the policy moved away from it.
"$SIM" position --positioner baseline --scenario "$B" --json >"$WORK/baseline.json" 2>/dev/null
[ "$(at "$WORK/baseline.json")" != "$expected" ] || fail "the tiny policy stays at the baseline"

write_campaign() {  # write_campaign FILE POLICY_FOLDER
  cat >"$1" <<JSON
{
  "name": "named-policy",
  "scenarios": [{"file": "$B", "set": ["env.episode_duration=30"]}],
  "rng_runs": [1, 2],
  "positioners": ["oracle", {"rl": {"policy": "$2"}}],
  "eval": {"duration": 1, "warmup": 0.5},
  "retries": 0,
  "job_timeout_s": 300
}
JSON
}

# Refused at submit, each in one line naming the positioner, with nothing run or written.
refused() {  # refused WHAT POLICY_FOLDER EXPECTED_TEXT
  write_campaign "$WORK/bad.json" "$2"
  if "$CAMPAIGN" run "$WORK/bad.json" --dry-run >"$WORK/bad.out" 2>"$WORK/bad.err"; then
    fail "$1: --dry-run accepted it"
  fi
  [ "$(wc -l <"$WORK/bad.err")" -eq 1 ] || fail "$1: not one line: $(cat "$WORK/bad.err")"
  grep -q "/positioners/1/rl/policy: .*$3" "$WORK/bad.err" || fail "$1: $(cat "$WORK/bad.err")"
}
refused "a missing folder" "policies/none" "does not exist"
mkdir -p "$WORK/policies/empty"
refused "a folder without a policy" "policies/empty" "holds no policy"
mkdir -p "$WORK/policies/bad-manifest"
cp "$WORK/policies/tiny/scenario.json" "$WORK/policies/bad-manifest/"
echo '{"format": ' >"$WORK/policies/bad-manifest/policy.json"
echo 'zip' >"$WORK/policies/bad-manifest/model.pt"
refused "a malformed manifest" "policies/bad-manifest" "policy.json is not JSON"
cp -r "$WORK/policies/tiny" "$WORK/policies/big"
head -c 16777217 /dev/zero >"$WORK/policies/big/policy.pt"
refused "an oversized policy" "policies/big" "holds more than 16777216 bytes"
"$SIM" train --scenario "$SRC/campaigns/scenarios/c.json" --fidelity analytic --seed 1 \
  --episodes 1 --out "$WORK/policies/on-c" >"$WORK/train_c.log" 2>&1 \
  || fail "training on C failed: $(tail -n 3 "$WORK/train_c.log")"
refused "a policy of another scenario" "policies/on-c" "(trained on C) does not fit /scenarios/0"
[ ! -e "$DB" ] || fail "a refused campaign wrote $DB"

write_campaign "$WORK/campaign.json" "policies/tiny"
run_campaign "$WORK/campaign.json" --no-progress

# 2 position jobs (oracle, rl+tiny) + 2 x 2 evals; nothing trained.
expect_complete "$DB" 6
expect_eq "train jobs" "$(sql "$DB" "SELECT COUNT(*) FROM jobs WHERE kind = 'train'")" 0
expect_eq "eval labels" "$(sql "$DB" "SELECT group_concat(positioner, ' ') FROM (SELECT DISTINCT
  positioner FROM v_eval_runs ORDER BY positioner)")" "oracle rl+tiny"
sha=$(sql "$DB" "SELECT policy_sha256 FROM jobs WHERE key = 'position/B/rl+tiny'")
[ ${#sha} -eq 64 ] || fail "the rl position job has no policy sha256: '$sha'"
[ -d "$WORK/rlpos.artifacts/policies/$sha" ] \
  || fail "the coordinator kept no policy $sha beside the database"
for run in 1 2; do
  got=$(sql "$DB" "SELECT printf('%.3f,%.3f,%.3f', x, y, z) FROM v_eval_runs
    WHERE positioner = 'rl+tiny' AND rng_run = $run")
  expect_eq "rl+tiny eval of run $run" "$got" "$expected"
done
grep -q "^B  *rl+tiny " "$WORK/out.txt" || fail "the printed summary has no rl+tiny row: $(cat "$WORK/out.txt")"

# The same campaign with another policy (the same folder name, other weights) is another campaign.
"$SIM" train --scenario "$B" --set env.episode_duration=30 --fidelity analytic --seed 2 \
  --episodes 3 --out "$WORK/other/tiny" >"$WORK/train2.log" 2>&1 \
  || fail "training seed 2 failed: $(tail -n 3 "$WORK/train2.log")"
write_campaign "$WORK/other/campaign.json" "tiny"
same=$("$CAMPAIGN" run "$WORK/campaign.json" --dry-run | sed -n 's/^campaign \([0-9a-f]*\) .*/\1/p')
other=$("$CAMPAIGN" run "$WORK/other/campaign.json" --dry-run | sed -n 's/^campaign \([0-9a-f]*\) .*/\1/p')
expect_eq "the dry run's campaign id" "$same" "$ID"
[ -n "$other" ] && [ "$other" != "$ID" ] || fail "another policy kept the campaign id $ID"

# A policy for any scenario (trained on generated ones, none of them B or C) enters a campaign on
# B and C, and each eval sits where `rlpos-sim position --policy` puts it in that scenario.
"$SIM" train --generated urban,open --steps 240 --seed 3 --validation-scenarios 2 \
  --set agent.ppo.num_envs=4 --set agent.train_episode_steps=10 --set agent.ppo.rollout_steps=10 \
  --set agent.hidden=[16] --set env.coverage_map=4 --set env.observed_ues=4 --set env.height_map=3 \
  --out "$WORK/policies/gen" >"$WORK/train_gen.log" 2>&1 \
  || fail "training across scenarios failed: $(tail -n 3 "$WORK/train_gen.log")"
C=$SRC/campaigns/scenarios/c.json
for s in B C; do
  file=$B; [ "$s" = C ] && file=$C
  "$SIM" position --positioner rl --policy "$WORK/policies/gen" --scenario "$file" --json \
    >"$WORK/gen_$s.json" 2>"$WORK/gen_$s.log" || fail "position in $s: $(cat "$WORK/gen_$s.log")"
done
cat >"$WORK/general.json" <<JSON
{
  "name": "general-policy",
  "scenarios": ["$B", "$C"],
  "rng_runs": [1, 1],
  "positioners": [{"rl": {"policy": "policies/gen"}}],
  "eval": {"duration": 1, "warmup": 0.5},
  "retries": 0,
  "job_timeout_s": 300
}
JSON
"$CAMPAIGN" run "$WORK/general.json" --workers 2 --db "$WORK/general.db" --tag "$TAG" --no-progress \
  >"$WORK/gen_out.txt" 2>"$WORK/gen_err.txt" || { rc=$?; cat "$WORK/gen_err.txt" >&2; fail "general run exited $rc"; }
expect_complete "$WORK/general.db" 4
for s in B C; do
  got=$(sql "$WORK/general.db" "SELECT printf('%.3f,%.3f,%.3f', x, y, z) FROM v_eval_runs
    WHERE positioner = 'rl+gen' AND scenario = '$s'")
  expect_eq "rl+gen eval in $s" "$got" "$(at "$WORK/gen_$s.json")"
done
echo "ok: named-policy campaign $ID; rl+tiny evaluated at $expected, the policy's own placement;"
echo "    a policy for any scenario placed in B and C as on this machine"
