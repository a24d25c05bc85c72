#pragma once
// An exclusive advisory lock on a file (flock), held for the object's lifetime and released by
// the kernel even when the process is killed. The coordinator holds one next to its database:
// the database has one writer, and a second coordinator on it stops with a clear error instead
// of assigning the first one's jobs.
#include <string>

namespace rlpos {

class ExclusiveFileLock {
 public:
  // Throws std::runtime_error naming the file (and the holder's pid when known) if another
  // process holds it or it cannot be created.
  explicit ExclusiveFileLock(const std::string& file);
  ~ExclusiveFileLock();
  ExclusiveFileLock(const ExclusiveFileLock&) = delete;
  ExclusiveFileLock& operator=(const ExclusiveFileLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace rlpos
