// Output files written all or nothing. Every output's bytes are produced first; then each regular (or new)
// target gets a temporary beside it, each existing non-regular target (a device, a FIFO, /dev/stdout) is written
// directly (never renamed over: that would replace the node for every other process), and only when all of
// them succeeded are the temporaries renamed onto their targets. A failure, SIGINT, SIGTERM or SIGHUP on the way
// removes the temporaries and leaves every existing output as it was (a signal the process handles itself, as a
// render's graceful stop, waits until the commit is done).
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace vkmc {

class OutputSet {
 public:
  void add(const std::string& path, std::string bytes);
  // Throws vkmc::Error naming the output that failed.
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> files_;
};

// Removes the temporaries of commits in flight; async-signal-safe, for a signal handler that ends the process.
void removePendingTemporaries() noexcept;
// Whether a commit is renaming its temporaries onto their targets; a handler that would end the process defers its
// signal instead, and the commit raises it once every rename is done (both async-signal-safe).
bool outputRenamesInFlight() noexcept;
void deferSignalUntilRenamed(int sig) noexcept;

// One output, as an OutputSet of one.
void writeFileAtomically(const std::string& path, const std::string& bytes);

// Refuses, before any work, output paths that are folders, lie in missing folders, name the same file as another
// output (flag, path pairs; empty paths are unused outputs) or as one of the inputs. Character devices such as
// /dev/null may be named twice.
void checkOutputPaths(const std::vector<std::pair<std::string, std::string>>& outputs, const std::vector<std::string>& inputs);

}  // namespace vkmc
