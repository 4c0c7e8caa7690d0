// The lock file (see the header). A holder removes its lock file while it still holds the lock, so a process that
// opened the old file before the removal finds, once it holds that lock, that the path names another file (or
// none) and tries again: at most one process holds the lock of the file the path names.
#include "io/file_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "error.h"

namespace vkmc {

FileLock::FileLock(const std::string& path, const std::string& what) : lockPath_(path + ".lock") {
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(lockPath_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0)
      throw Error("cannot lock " + what + " '" + path + "': " + std::strerror(errno) + " (its lock '" + lockPath_ + "')");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      ::close(fd_);
      fd_ = -1;
      if (err == EWOULDBLOCK)
        throw Error(what + " '" + path + "' is in use by another vkmc render (its lock '" + lockPath_ + "')");
      throw Error("cannot lock " + what + " '" + path + "': " + std::strerror(err));
    }
    struct stat held {
    }, named{};
    if (::fstat(fd_, &held) == 0 && ::lstat(lockPath_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev)
      return;
    ::close(fd_);  // the holder before removed it meanwhile: lock the file the path names now
    fd_ = -1;
  }
  throw Error("cannot lock " + what + " '" + path + "': its lock file keeps changing");
}

FileLock::~FileLock() {
  if (fd_ < 0) return;
  // Only the lock file this lock holds: a file since renamed onto its path is someone's, not vkmc's lock.
  struct stat held {
  }, named{};
  if (::fstat(fd_, &held) == 0 && ::lstat(lockPath_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
      held.st_dev == named.st_dev)
    ::unlink(lockPath_.c_str());
  ::close(fd_);
}

}  // namespace vkmc
