#include "worker/daemon/job_attempt.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "common/hash/sha256.h"
#include "common/scenario/number_text.h"
#include "common/wire/limits.h"
#include "common/wire/policy_bundle_files.h"
#include "worker/daemon/sim_command.h"

namespace rlpos {
namespace fs = std::filesystem;

namespace {

std::string SafeComponent(const std::string& part) {
  std::string out;
  for (char c : part) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-' || c == '@';
    out += ok ? c : '_';
  }
  if (out.empty() || out == "." || out == "..")
    out = "_" + out;
  return out;
}

std::string ReadFile(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string Trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos)
    return "";
  return s.substr(begin, s.find_last_not_of(" \t\r\n") - begin + 1);
}

}  // namespace

std::vector<ArtifactFile> ReadTrainArtifacts(const std::string& out_folder) {
  std::vector<ArtifactFile> out;
  std::size_t total = 0;
  for (const auto& name : TrainArtifactNames()) {
    const fs::path file = fs::path(out_folder) / name;
    std::error_code error;
    const auto size = fs::file_size(file, error);
    if (error)
      continue;  // not written by this trainer
    if (size > wire::kMaxArtifactBytes || total + size > wire::kMaxArtifactsTotal) {
      throw std::runtime_error("artifact " + name + " (" + std::to_string(size) +
                               " bytes) is beyond what a result may carry (" +
                               std::to_string(wire::kMaxArtifactBytes) + " bytes a file, " +
                               std::to_string(wire::kMaxArtifactsTotal) + " in all)");
    }
    total += size;
    ArtifactFile artifact;
    artifact.name = name;
    artifact.data = ReadFile(file.string());
    artifact.sha256 = Sha256Hex(artifact.data);
    out.push_back(std::move(artifact));
  }
  return out;
}

std::string AttemptFolder(const std::string& work_dir, const std::string& job_id, int attempt) {
  fs::path folder(work_dir);
  std::stringstream parts(job_id);
  for (std::string part; std::getline(parts, part, '/');)
    folder /= SafeComponent(part);
  return (folder / ("attempt" + std::to_string(attempt))).string();
}

std::string TailOfLog(const std::string& file, int lines, std::size_t max_chars) {
  std::stringstream text(ReadFile(file));
  std::vector<std::string> kept;
  for (std::string line; std::getline(text, line);) {
    // Progress bars redraw with '\r': the text after the last one is what is on screen.
    line = Trim(line);
    if (const auto cr = line.rfind('\r'); cr != std::string::npos)
      line = Trim(line.substr(cr + 1));
    if (!line.empty())
      kept.push_back(line);
  }
  const std::size_t first = kept.size() > static_cast<std::size_t>(lines) ? kept.size() - lines : 0;
  std::string out;
  for (std::size_t i = first; i < kept.size(); ++i)
    out += (out.empty() ? "" : " | ") + kept[i];
  if (out.size() > max_chars)
    out = "..." + out.substr(out.size() - max_chars);
  return out;
}

JobAttempt::JobAttempt(JobOrder order, const nlohmann::json& scenario, const std::string& work_dir,
                       const std::string& sim_binary)
    : order_(std::move(order)), folder_(AttemptFolder(work_dir, order_.job_id, order_.attempt)) {
  std::error_code error;
  fs::remove_all(folder_, error);  // a leftover of an earlier worker with this id
  fs::create_directories(folder_, error);
  if (error)
    throw std::runtime_error(folder_ + ": " + error.message());
  {
    const std::string text = scenario.dump(2) + '\n';
    std::ofstream out(fs::path(folder_) / kScenarioFileName);
    out << text;
    if (!out)
      throw std::runtime_error(folder_ + "/" + kScenarioFileName + ": cannot write");
    scenario_sha256_ = Sha256Hex(text);
  }
  // A named policy, checked against its sha256 with the order, is unpacked into a folder the
  // worker names by that hash: slots and attempts that fly it share it.
  const std::string policy_dir =
      order_.policy ? WritePolicyBundle(*order_.policy, WorkerPoliciesDir(work_dir)) : "";
  const auto argv = SimCommandLine(order_, sim_binary, folder_, policy_dir);
  {
    std::ofstream command(fs::path(folder_) / "command.txt");
    for (const auto& a : argv)
      command << a << '\n';
  }
  started_ = std::chrono::steady_clock::now();
  child_ = std::make_unique<ChildProcess>(argv, (fs::path(folder_) / "stdout.json").string(),
                                          (fs::path(folder_) / "stderr.log").string());
}

std::string JobAttempt::Key() const {
  return order_.job_id + "#" + std::to_string(order_.attempt);
}

std::optional<JobOutcome> JobAttempt::Poll() {
  JobOutcome outcome;
  if (!child_->Poll()) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    if (elapsed <= order_.timeout_s)
      return std::nullopt;
    child_->Kill();
    outcome.error = "timed out after " + FormatNumber(order_.timeout_s) + " s";
    return outcome;
  }
  const ChildExit& exit = child_->exit_status();
  const std::string stderr_file = (fs::path(folder_) / "stderr.log").string();
  if (exit.exited && exit.code == 0) {
    const std::string text = ReadFile((fs::path(folder_) / "stdout.json").string());
    try {
      outcome.result_json = nlohmann::json::parse(text).dump();
      if (order_.params.kind == JobKind::kTrain)
        outcome.artifacts = ReadTrainArtifacts((fs::path(folder_) / kOutFolderName).string());
      outcome.succeeded = true;
    } catch (const nlohmann::json::exception&) {
      outcome.error = "rlpos-sim ended well but printed no JSON result";
    } catch (const std::runtime_error& e) {
      outcome.error = e.what();
    }
    return outcome;
  }
  const std::string tail = TailOfLog(stderr_file);
  outcome.error =
      (tail.empty() ? std::string("rlpos-sim failed") : tail) + " [" + Describe(exit) + "]";
  return outcome;
}

void JobAttempt::Stop() {
  child_->Kill();
}

std::string JobAttempt::ProgressLine() const {
  return TailOfLog((fs::path(folder_) / "stderr.log").string(), 1, 200);
}

}  // namespace rlpos
