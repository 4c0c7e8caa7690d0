// An exclusive lock on a path, held for an object's lifetime: a lock file beside it (PATH.lock) under flock(2),
// removed when released. Two renders that name one checkpoint would overwrite each other's; the second is refused.
#pragma once
#include <string>

namespace vkmc {

class FileLock {
 public:
  // Throws vkmc::Error when another process holds the lock, or when the lock file cannot be made.
  explicit FileLock(const std::string& path, const std::string& what);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  std::string lockPath_;
  int fd_ = -1;
};

}  // namespace vkmc
