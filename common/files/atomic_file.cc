#include "common/files/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace rlpos {
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& what, int error) {
  throw std::runtime_error("cannot write " + path + ": " + what + ": " + std::strerror(error));
}

}  // namespace

void CreateReportDir(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) {
    throw std::runtime_error("cannot create report folder " + dir + ": " + error.message());
  }
  if (!std::filesystem::is_directory(dir, error)) {
    throw std::runtime_error("cannot create report folder " + dir + ": not a folder");
  }
}

void WriteFileAtomically(const std::string& path, const std::string& content) {
  const std::filesystem::path target(path);
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
  std::string pattern = (dir / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  std::vector<char> temp(pattern.begin(), pattern.end());
  temp.push_back('\0');
  const int fd = mkstemp(temp.data());
  if (fd < 0)
    Fail(path, "cannot create a temporary file in " + dir.string(), errno);
  const auto abandon = [&](const std::string& what, int error) {
    close(fd);
    unlink(temp.data());
    Fail(path, what, error);
  };
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = write(fd, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR)
        continue;
      abandon("write failed", errno);
    }
    done += static_cast<std::size_t>(n);
  }
  if (fchmod(fd, 0644) != 0)
    abandon("chmod failed", errno);
  if (fsync(fd) != 0)
    abandon("fsync failed", errno);
  if (close(fd) != 0) {
    const int error = errno;
    unlink(temp.data());
    Fail(path, "close failed", error);
  }
  if (std::rename(temp.data(), path.c_str()) != 0) {
    const int error = errno;
    unlink(temp.data());
    Fail(path, "rename failed", error);
  }
}

}  // namespace rlpos
