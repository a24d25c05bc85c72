// Known answers: trains ALGORITHM (dqn, ppo: CartPole-v1; sac: Pendulum-v1) with train seed SEED
// until its greedy policy reaches the solved level, printing each greedy evaluation; exit 0 if
// solved within the budget, 1 if not, 2 on bad arguments.
//   rlpos-bench-known-answers ALGORITHM [SEED]
#include <ATen/Parallel.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "tests/bench/known_answer.h"
#include "tests/support/program_usage.h"

namespace {

// SEED: a whole number, 0 .. 2^53 (as agent.seed).
bool ParseSeed(const std::string& text, std::uint64_t& seed) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 16)
    return false;
  seed = std::stoull(text);
  return seed <= 9007199254740991ULL;
}

}  // namespace

int main(int argc, char** argv) {
  constexpr char kUsage[] = "usage: rlpos-bench-known-answers dqn|ppo|sac [SEED]\n";
  if (rlpos::testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  if (argc < 2 || argc > 3)
    return rlpos::testing::UsageError(kUsage);
  std::uint64_t seed = 1;
  if (argc == 3 && !ParseSeed(argv[2], seed)) {
    std::fprintf(stderr, "error: SEED: '%s' is not a whole number in [0, 2^53]\n", argv[2]);
    return 2;
  }
  rlpos::KnownAnswerProblem problem;
  try {
    problem = rlpos::KnownAnswerProblemFor(argv[1]);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: ALGORITHM: %s\n", e.what());
    return 2;
  }
  // One thread: small networks gain nothing from more, and the numbers stay the same bytes.
  at::set_num_threads(1);
  const std::string algorithm = argv[1];
  std::printf(
      "%s on %s, seed %llu: solved at a mean greedy return >= %g over %d episodes, "
      "within %lld steps\n",
      algorithm.c_str(), problem.env_name.c_str(), static_cast<unsigned long long>(seed),
      problem.solved_return, problem.eval_episodes, static_cast<long long>(problem.budget_steps));
  const auto result = rlpos::RunKnownAnswer(problem, seed, [](const rlpos::GreedyEvaluation& e) {
    std::printf("  steps %7lld  greedy mean %8.2f over %3d episodes%s  (%.1f s)\n",
                static_cast<long long>(e.steps), e.mean_return, e.episodes,
                e.complete ? "" : " (stopped: cannot reach the level)", e.wall_seconds);
    std::fflush(stdout);
  });
  if (result.solved_at) {
    std::printf("RESULT %s seed %llu solved_at %lld wall_s %.1f\n", algorithm.c_str(),
                static_cast<unsigned long long>(seed), static_cast<long long>(*result.solved_at),
                result.wall_seconds);
    return 0;
  }
  std::printf("RESULT %s seed %llu unsolved steps %lld wall_s %.1f\n", algorithm.c_str(),
              static_cast<unsigned long long>(seed), static_cast<long long>(result.steps),
              result.wall_seconds);
  return 1;
}
