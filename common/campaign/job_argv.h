#pragma once
// The rlpos-sim command line of a job. A job's argv is stored with placeholders that are bound
// late: {position} by the results store when the job's dependency succeeds, {out_dir} by the
// worker (its own folder for the job's artifacts). argv[0] is "rlpos-sim": the worker runs its
// sibling binary of that name.
#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace rlpos {

inline const char kSimBinary[] = "rlpos-sim";
inline const char kPositionPlaceholder[] = "{position}";
inline const char kOutDirPlaceholder[] = "{out_dir}";

// Shortest text that reads back as the same double ("2", "0.5", "44.5").
std::string FormatNumber(double x);
// "x,y,z" as rlpos-sim --position takes it.
std::string FormatPosition(const Vec3& p);

// Replaces every argument equal to `placeholder` by `value`; returns how many it replaced.
int BindPlaceholder(std::vector<std::string>& argv, const std::string& placeholder,
                    const std::string& value);

// True if some argument is still one of the placeholders above.
bool HasUnboundPlaceholder(const std::vector<std::string>& argv);

}  // namespace rlpos
