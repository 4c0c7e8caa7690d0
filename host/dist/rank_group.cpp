// RankGroup over MPI when built with it (VKMC_HAVE_MPI), else a group of one.
#include "dist/rank_group.h"

#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

#ifdef VKMC_HAVE_MPI
#define OMPI_SKIP_MPICXX 1  // the C API only: the C++ bindings would need libmpi_cxx
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

#include "error.h"

namespace vkmc {

bool builtWithMpi() {
#ifdef VKMC_HAVE_MPI
  return true;
#else
  return false;
#endif
}

bool launchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (std::getenv(name)) return true;
  return false;
}

RankGroup& RankGroup::world() {
  static RankGroup group;
  return group;
}

RankGroup::RankGroup() {
#ifdef VKMC_HAVE_MPI
  // Only under a launcher: a plain `vkmc render` never pays for MPI's start-up (or its messages).
  if (!launchedByMpi()) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  rank_ = uint32_t(rank), size_ = uint32_t(size);
  mpi_ = true;
#else
  if (launchedByMpi() && std::getenv("OMPI_COMM_WORLD_SIZE") && std::atoi(std::getenv("OMPI_COMM_WORLD_SIZE")) > 1)
    throw Error(
        "started by mpirun with several ranks, but this vkmc was built without MPI (install libopenmpi-dev and "
        "rebuild): each rank would render the whole image alone");
#endif
}

std::string RankGroup::describe() const {
  char host[256] = "?";
  ::gethostname(host, sizeof(host) - 1);
  return "rank " + std::to_string(rank_) + " of " + std::to_string(size_) + " on " + host;
}

std::vector<std::string> RankGroup::gather(const std::string& mine) const {
  if (!mpi_) return {mine};
#ifdef VKMC_HAVE_MPI
  // Sizes first (bytes may pass 2 GiB in total, so they travel in chunks of at most 1 GiB per rank).
  long long length = static_cast<long long>(mine.size());
  std::vector<long long> lengths(size_);
  MPI_Gather(&length, 1, MPI_LONG_LONG, lengths.data(), 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  std::vector<std::string> all;
  if (rank_ == 0) {
    all.resize(size_);
    all[0] = mine;
    for (uint32_t r = 1; r < size_; ++r) {
      all[r].resize(size_t(lengths[r]));
      for (long long at = 0; at < lengths[r];) {
        int chunk = int(std::min<long long>(lengths[r] - at, 1ll << 30));
        MPI_Recv(all[r].data() + at, chunk, MPI_BYTE, int(r), 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        at += chunk;
      }
    }
  } else {
    for (long long at = 0; at < length;) {
      int chunk = int(std::min<long long>(length - at, 1ll << 30));
      MPI_Send(mine.data() + at, chunk, MPI_BYTE, 0, 7, MPI_COMM_WORLD);
      at += chunk;
    }
  }
  return all;
#else
  return {mine};
#endif
}

void RankGroup::broadcast(std::string& bytes) const {
  if (!mpi_) return;
#ifdef VKMC_HAVE_MPI
  long long length = static_cast<long long>(bytes.size());
  MPI_Bcast(&length, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  bytes.resize(size_t(length));
  for (long long at = 0; at < length;) {
    int chunk = int(std::min<long long>(length - at, 1ll << 30));
    MPI_Bcast(bytes.data() + at, chunk, MPI_BYTE, 0, MPI_COMM_WORLD);
    at += chunk;
  }
#endif
}

int RankGroup::maxOver(int mine) const {
  if (!mpi_) return mine;
  int result = mine;
#ifdef VKMC_HAVE_MPI
  MPI_Allreduce(&mine, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
#endif
  return result;
}

void RankGroup::abort(int code) const {
#ifdef VKMC_HAVE_MPI
  if (mpi_) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::_Exit(code);
}

void RankGroup::finish() {
#ifdef VKMC_HAVE_MPI
  if (mpi_) MPI_Finalize();
#endif
  mpi_ = false;
}

}  // namespace vkmc
