// All-or-nothing output files (see the header).
#include "io/output_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include "error.h"

namespace vkmc {
namespace fs = std::filesystem;

namespace {

// Temporaries in flight, for the signal handler (fixed storage: only async-signal-safe calls in the handler).
constexpr int kMaxPending = 16;
char pendingPaths[kMaxPending][4096];
std::atomic<bool> pendingUsed[kMaxPending];

// While a commit renames its temporaries, a signal that would end the process waits for the renames (a signal
// for the process may land in any thread, and sigprocmask holds back only the renaming one's).
std::atomic<bool> renaming{false};
std::atomic<int> deferredSignal{0};

void removePendingAndReraise(int sig) {
  if (renaming.load()) return deferSignalUntilRenamed(sig);
  removePendingTemporaries();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

class PendingTemporary {
 public:
  explicit PendingTemporary(const std::string& path) : path_(path) {
    for (int i = 0; i < kMaxPending && slot_ < 0; ++i) {
      bool expected = false;
      if (path.size() < sizeof(pendingPaths[i]) && !pendingUsed[i].load()) {
        std::memcpy(pendingPaths[i], path.c_str(), path.size() + 1);
        if (pendingUsed[i].compare_exchange_strong(expected, true)) slot_ = i;
      }
    }
  }
  ~PendingTemporary() {
    if (!committed_) ::unlink(path_.c_str());
    if (slot_ >= 0) pendingUsed[slot_].store(false);
  }
  void committed() { committed_ = true; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int slot_ = -1;
  bool committed_ = false;
};

// For the duration of a commit: where SIGINT, SIGTERM or SIGHUP would kill the process (their default), the
// cleanup handler, which removes the temporaries first. A signal the process ignores stays ignored, and one it
// handles (a render's graceful stop) keeps its handler: that one handler serves every thread, whichever the signal
// lands in, and the commit completes before the stop is acted on. SIGPIPE is ignored so that a reader closing a
// FIFO early is a write error, not a kill.
class SignalGuard {
 public:
  SignalGuard() {
    for (int s : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction now {};
      sigaction(s, nullptr, &now);
      if (now.sa_handler != SIG_DFL || (now.sa_flags & SA_SIGINFO)) continue;
      old_.push_back({s, std::signal(s, removePendingAndReraise)});
    }
    old_.push_back({SIGPIPE, std::signal(SIGPIPE, SIG_IGN)});
  }
  ~SignalGuard() {
    for (auto& [s, h] : old_) std::signal(s, h);
  }

 private:
  std::vector<std::pair<int, void (*)(int)>> old_;
};

// Blocks the cleanup signals while the temporaries are renamed: they then arrive after every rename, never
// between two of them.
class SignalBlock {
 public:
  SignalBlock() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
    sigprocmask(SIG_BLOCK, &set, &old_);
    renaming.store(true);
  }
  ~SignalBlock() {
    renaming.store(false);
    sigprocmask(SIG_SETMASK, &old_, nullptr);
    // A signal that arrived in another thread meanwhile ends the process now, the renames done.
    if (int sig = deferredSignal.exchange(0)) {
      std::signal(sig, SIG_DFL);
      std::raise(sig);
    }
  }

 private:
  sigset_t old_;
};

void writeAll(int fd, const std::string& bytes, const std::string& path) {
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error("cannot write '" + path + "': " + std::strerror(n < 0 ? errno : EIO));
    done += size_t(n);
  }
}

// The file a path names once symlinks are followed, existing or not (a symlink is kept and its target written).
std::string resolved(const std::string& path) {
  fs::path p = path;
  std::error_code ec;
  for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++hops) {
    fs::path target = fs::read_symlink(p, ec);
    if (ec) break;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  return p.string();
}

// A short name (NAME_MAX-safe whatever the target's length) in the target's folder, so the rename is atomic.
// `attempt` varies it: a temporary left by a killed run with the same PID must not block this one.
std::string temporaryBeside(const std::string& path, int attempt) {
  static std::atomic<int> counter{0};
  fs::path parent = fs::path(path).parent_path();
  std::string name = ".vkmc-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                     (attempt ? "-" + std::to_string(attempt) : "") + ".tmp";
  return (parent.empty() ? fs::path(name) : parent / name).string();
}

}  // namespace

bool outputRenamesInFlight() noexcept { return renaming.load(); }
void deferSignalUntilRenamed(int sig) noexcept { deferredSignal.store(sig); }

void removePendingTemporaries() noexcept {
  for (int i = 0; i < kMaxPending; ++i)
    if (pendingUsed[i].load()) ::unlink(pendingPaths[i]);
}

void OutputSet::add(const std::string& path, std::string bytes) { files_.emplace_back(path, std::move(bytes)); }

void OutputSet::commit() {
  SignalGuard guard;
  struct Staged {
    std::unique_ptr<PendingTemporary> temporary;
    std::string target, path;
  };
  std::vector<Staged> staged;
  std::vector<std::pair<std::string, const std::string*>> direct;
  for (const auto& [path, bytes] : files_) {
    // What the path names once symlinks are followed (stat follows them; /dev/stdout may lead to a pipe, whose
    // link target is no path at all): anything but a regular file is written directly through the path itself.
    struct stat st {};
    bool exists = ::stat(path.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) throw Error("cannot write '" + path + "': it is a folder");
    if (exists && !S_ISREG(st.st_mode)) {
      if (!S_ISCHR(st.st_mode) && !S_ISFIFO(st.st_mode)) throw Error("cannot write '" + path + "': not a file, device or FIFO");
      direct.emplace_back(path, &bytes);
      continue;
    }
    std::string target = resolved(path);
    int fd = -1;
    std::unique_ptr<PendingTemporary> tmp;
    for (int attempt = 0; fd < 0 && attempt < 100; ++attempt) {
      std::string name = temporaryBeside(target, attempt);
      fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
      if (fd >= 0)
        tmp = std::make_unique<PendingTemporary>(name);
      else if (errno != EEXIST)
        break;
    }
    if (fd < 0) throw Error("cannot write '" + path + "': " + std::strerror(errno));
    staged.push_back({std::move(tmp), target, path});
    try {
      if (exists) ::fchmod(fd, st.st_mode & 07777);  // a replaced file keeps its permissions
      writeAll(fd, bytes, path);
      if (::fsync(fd) != 0) throw Error("cannot write '" + path + "': " + std::strerror(errno));
    } catch (...) {
      ::close(fd);
      throw;
    }
    if (::close(fd) != 0) throw Error("cannot write '" + path + "': " + std::strerror(errno));
  }
  // Devices and FIFOs: opened without creating or truncating; a FIFO without a reader fails instead of blocking.
  for (const auto& [path, bytes] : direct) {
    int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw Error("cannot write '" + path + "': " + std::strerror(errno));
    int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    try {
      writeAll(fd, *bytes, path);
    } catch (...) {
      ::close(fd);
      throw;
    }
    ::close(fd);
  }
  SignalBlock block;
  for (Staged& s : staged) {
    if (::rename(s.temporary->path().c_str(), s.target.c_str()) != 0)
      throw Error("cannot write '" + s.path + "': " + std::strerror(errno));
    s.temporary->committed();
  }
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  OutputSet set;
  set.add(path, bytes);
  set.commit();
}

void checkOutputPaths(const std::vector<std::pair<std::string, std::string>>& outputs, const std::vector<std::string>& inputs) {
  auto sameFile = [](const std::string& a, const std::string& b) {
    std::error_code ea, eb;
    if (fs::exists(a, ea) && fs::exists(b, eb)) return fs::equivalent(a, b, ea) && !ea;
    fs::path ca = fs::weakly_canonical(resolved(a), ea), cb = fs::weakly_canonical(resolved(b), eb);
    return !ea && !eb && ca == cb;
  };
  auto isCharDevice = [](const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
  };
  for (size_t i = 0; i < outputs.size(); ++i) {
    const auto& [flag, path] = outputs[i];
    if (path.empty()) continue;
    fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (parent.empty()) parent = ".";
    if (!fs::is_directory(parent, ec)) throw Error(flag + ": folder '" + parent.string() + "' does not exist");
    if (fs::is_directory(path, ec)) throw Error(flag + ": '" + path + "' is a folder");
    for (const std::string& in : inputs)
      if (!in.empty() && sameFile(path, in))
        throw Error(flag + ": '" + path + "' is an input of this command; it would be overwritten");
    for (size_t k = 0; k < i; ++k)
      if (!outputs[k].second.empty() && sameFile(path, outputs[k].second) && !isCharDevice(path))
        throw Error(flag + " and " + outputs[k].first + " name the same file '" + path + "'");
  }
}

}  // namespace vkmc
