#!/usr/bin/env bash
# Known answers over several train seeds (docs/agents.md#known-answers): DQN and PPO on CartPole-v1,
# SAC on Pendulum-v1; for each algorithm and seed, the training steps at which the greedy policy
# first reached the solved level (or "unsolved" within the budget), then the worst per
# algorithm. CI runs seed 1 only (ctest -L known_answer).
#   scripts/bench_known_answers.sh [BUILD_DIR] [SEEDS] [ALGORITHMS]
#   e.g. scripts/bench_known_answers.sh build "1 2 3 4 5" "dqn ppo sac"
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-"$here/build"}/bin/rlpos-bench-known-answers
seeds=${2:-"1 2 3 4 5"}
algorithms=${3:-"dqn ppo sac"}
[ -x "$bin" ] || { echo "bench: $bin not built (cmake --build build --target rlpos-bench-known-answers)" >&2; exit 1; }

results=$(mktemp)
trap 'rm -f "$results"' EXIT
printf '%-5s %-12s %5s %16s %8s\n' algo env seed steps_to_solved wall_s
for algorithm in $algorithms; do
  for seed in $seeds; do
    # The last line: "RESULT <algo> seed <n> solved_at <steps> wall_s <s>" or "... unsolved ...".
    line=$("$bin" "$algorithm" "$seed" | tail -n 1 || true)
    read -r _ _ _ _ outcome steps _ wall <<<"$line"
    [ "$outcome" = solved_at ] || steps=unsolved
    env=CartPole-v1
    [ "$algorithm" = sac ] && env=Pendulum-v1
    printf '%-5s %-12s %5s %16s %8s\n' "$algorithm" "$env" "$seed" "$steps" "$wall"
    echo "$algorithm $steps" >>"$results"
  done
done
echo
printf '%-5s %16s\n' algo worst_steps
for algorithm in $algorithms; do
  awk -v a="$algorithm" '$1 == a { if ($2 == "unsolved") u = 1; else if ($2 > w) w = $2 }
    END { printf "%-5s %16s\n", a, u ? "unsolved" : w }' "$results"
done
