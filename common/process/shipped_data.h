#pragma once
// The scenarios and policies RLpos ships, named instead of given as a path: `--scenario b`,
// `--policy generalist-1uav`. They live in share/rlpos beside the program's bin/: an install's
// /usr/share/rlpos/{campaigns/scenarios,policies}, a build's build/share/rlpos (links to the
// checkout), so that an installed program needs no checkout.
#include <string>

namespace rlpos {

enum class ShippedKind { kScenario, kPolicy };

// `given` itself when it is a path that exists, names a folder (has a '/') or is empty;
// otherwise the shipped scenario (`given` or `given`.json) or policy of that name where there is
// one, else `given` (whose error then names what the user typed).
std::string ResolveShipped(const std::string& given, ShippedKind kind);

}  // namespace rlpos
