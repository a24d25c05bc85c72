#include "common/process/executable_path.h"

#include <filesystem>
#include <stdexcept>

namespace rlpos {

std::string ExecutableDir() {
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    throw std::runtime_error("/proc/self/exe: " + error.message());
  return exe.parent_path().string();
}

}  // namespace rlpos
