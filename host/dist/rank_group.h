// The processes of one render. Under `mpirun` (when vkmc was built with MPI) they are MPI's world, each with its
// own device; otherwise the group is this process alone and every operation is local. The operations are the few
// a distributed render needs, each collective: every rank calls it, in the same order.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace vkmc {

class RankGroup {
 public:
  // The group this process belongs to. Joins MPI's world on the first call when launched by mpirun.
  static RankGroup& world();
  uint32_t rank() const { return rank_; }
  uint32_t size() const { return size_; }
  bool distributed() const { return size_ > 1; }
  bool isRoot() const { return rank_ == 0; }
  std::string describe() const;  // "rank 1 of 4 on HOST"

  // Rank 0 receives every rank's bytes in rank order (the others receive nothing).
  std::vector<std::string> gather(const std::string& mine) const;
  // Every rank receives rank 0's bytes.
  void broadcast(std::string& bytes) const;
  // The largest of the ranks' values, on every rank.
  int maxOver(int mine) const;
  // Ends every rank of the job at once (a failed rank must not leave the others waiting in a collective).
  [[noreturn]] void abort(int code) const;
  void finish();  // leaves MPI's world (MPI_Finalize) once the job is done

 private:
  RankGroup();
  uint32_t rank_ = 0, size_ = 1;
  bool mpi_ = false;
};

// Whether this binary was built with MPI (CMake found it); `vkmc info` and the report say so.
bool builtWithMpi();
// Whether this process was started by an MPI launcher (its environment says so), without joining MPI.
bool launchedByMpi();

}  // namespace vkmc
