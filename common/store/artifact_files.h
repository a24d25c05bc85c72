#pragma once
// Where a results database keeps the files its jobs sent home (wire/artifacts.h): a folder
// beside it, named after it ("results/rlpos.db" -> "results/rlpos.artifacts"), holding
// <campaign id>/<job key>/<name>. The artifacts table records each path relative to that folder,
// so the database and its folder can move together.
#include <string>

namespace rlpos {

std::string ArtifactsDirOf(const std::string& db_file);

// Where the named policies of its campaigns are kept: <artifacts>/policies/<sha256>/<name>
// (wire/policy_bundle_files.h), content-addressed, shared by the campaigns that name them.
std::string PoliciesDirOf(const std::string& db_file);

// "<campaign id>/<key>/<name>" of a job id "<campaign id>/<key>". Throws std::invalid_argument
// unless the job id is a safe path and the name a safe name (wire/identifiers.h): nothing
// outside the folder can be named.
std::string ArtifactRelativePath(const std::string& job_id, const std::string& name);

// The file an artifact row names: root/relative with links followed. Throws std::runtime_error
// saying why unless it is a regular file inside `root` (an absolute or escaping stored path, a
// link out of the folder, a missing file): a database is read, never trusted, as a path.
std::string ResolveArtifactFile(const std::string& root, const std::string& relative);

// Writes `data` to root/relative (creating its folders) atomically. Throws std::runtime_error
// naming the file.
void WriteArtifactFile(const std::string& root, const std::string& relative,
                       const std::string& data);

}  // namespace rlpos
