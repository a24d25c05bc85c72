#pragma once
// Policy bundles (wire/policy_bundle.h) and folders on disk: the client packs the folder a
// campaign names; the coordinator and the worker keep bundles in content-addressed folders
// (<root>/<sha256>) that they name themselves.
#include <string>

#include "common/wire/policy_bundle.h"

namespace rlpos {

// Packs the files of PolicyFileNames() that `dir` holds (anything else in it is not read);
// sizes are checked before a byte is read. Throws std::invalid_argument with one line: no such
// folder, no policy in it, too large, a format's file missing.
PolicyBundle ReadPolicyBundle(const std::string& dir);

// <root>/<sha256>.
std::string PolicyBundleDir(const std::string& root, const std::string& sha256);

// Makes PolicyBundleDir(root, bundle.sha256) hold exactly the bundle's files and returns it. A
// folder already there that holds the bundle is kept; anything else there is replaced. Written
// under a temporary name and renamed, so a reader (another slot) never sees half a policy.
// `bundle` must pass CheckPolicyBundle. Throws std::runtime_error naming the folder.
std::string WritePolicyBundle(const PolicyBundle& bundle, const std::string& root);

// The bundle kept at PolicyBundleDir(root, sha256), checked against its hash. Throws
// std::runtime_error when it is missing or does not match.
PolicyBundle ReadStoredPolicyBundle(const std::string& root, const std::string& sha256);

}  // namespace rlpos
