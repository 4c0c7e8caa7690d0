// RankGroup over MPI when built with it (VKMC_HAVE_MPI), else a group of one.
#include "dist/rank_group.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
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

#ifdef VKMC_HAVE_MPI
namespace {

// How long a rank waits for another before it ends the job: VKMC_RANK_TIMEOUT seconds, by default ten minutes (a
// pass of a large image on a slow device, or rank 0 writing a large checkpoint, must not look like a stopped rank).
double rankTimeoutSeconds() {
  static const double seconds = [] {
    const char* text = std::getenv("VKMC_RANK_TIMEOUT");
    const double v = text ? std::atof(text) : 0.0;
    return v > 0.0 ? v : 600.0;
  }();
  return seconds;
}

// Completes `request`, or ends the job with one line naming the rank that did not answer (a rank stopped by
// SIGSTOP, or hung, would otherwise keep every other rank in MPI forever).
void waitFor(MPI_Request& request, int peer, const char* what, const RankGroup& group) {
  const auto start = std::chrono::steady_clock::now();
  for (int polls = 0;; ++polls) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // A rank waiting on rank 0 waits half as long again: where rank 0 is alive it names the rank that is not.
    if (waited > rankTimeoutSeconds() * (peer == 0 && group.rank() != 0 ? 1.5 : 1.0)) {
      if (peer >= 0)
        std::fprintf(stderr, "vkmc: error: rank %d of %u did not answer for %.0f s (%s): it stopped or hung, so the job ends\n",
                     peer, group.size(), waited, what);
      else
        std::fprintf(stderr, "vkmc: error: a rank of %u did not answer for %.0f s (%s): it stopped or hung, so the job ends\n",
                     group.size(), waited, what);
      group.abort(1);
    }
    ::usleep(polls < 100 ? 50 : 2000);  // quick answers stay quick; a long wait costs no CPU
  }
}

}  // namespace
#endif

std::vector<std::string> RankGroup::gather(const std::string& mine) const {
  if (!mpi_) return {mine};
#ifdef VKMC_HAVE_MPI
  // Sizes first, then the bytes (which may pass 2 GiB in total: chunks of at most 1 GiB per rank), point to point,
  // so that rank 0 knows which rank did not answer.
  long long length = static_cast<long long>(mine.size());
  std::vector<std::string> all;
  if (rank_ == 0) {
    all.resize(size_);
    all[0] = mine;
    for (uint32_t r = 1; r < size_; ++r) {
      long long theirs = 0;
      MPI_Request request;
      MPI_Irecv(&theirs, 1, MPI_LONG_LONG, int(r), 6, MPI_COMM_WORLD, &request);
      waitFor(request, int(r), "gathering", *this);
      all[r].resize(size_t(theirs));
      for (long long at = 0; at < theirs;) {
        int chunk = int(std::min<long long>(theirs - at, 1ll << 30));
        MPI_Irecv(all[r].data() + at, chunk, MPI_BYTE, int(r), 7, MPI_COMM_WORLD, &request);
        waitFor(request, int(r), "gathering", *this);
        at += chunk;
      }
    }
  } else {
    MPI_Request request;
    MPI_Isend(&length, 1, MPI_LONG_LONG, 0, 6, MPI_COMM_WORLD, &request);
    waitFor(request, 0, "gathering", *this);
    for (long long at = 0; at < length;) {
      int chunk = int(std::min<long long>(length - at, 1ll << 30));
      MPI_Isend(mine.data() + at, chunk, MPI_BYTE, 0, 7, MPI_COMM_WORLD, &request);
      waitFor(request, 0, "gathering", *this);
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
  MPI_Request request;
  // Rank 0 waits on its own broadcast only while a receiver stalls, which it cannot name (peer -1).
  const int from = rank_ == 0 ? -1 : 0;
  MPI_Ibcast(&length, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD, &request);
  waitFor(request, from, "broadcasting", *this);
  bytes.resize(size_t(length));
  for (long long at = 0; at < length;) {
    int chunk = int(std::min<long long>(length - at, 1ll << 30));
    MPI_Ibcast(bytes.data() + at, chunk, MPI_BYTE, 0, MPI_COMM_WORLD, &request);
    waitFor(request, from, "broadcasting", *this);
    at += chunk;
  }
#endif
}

int RankGroup::maxOver(int mine) const {
  if (!mpi_) return mine;
  int result = mine;
#ifdef VKMC_HAVE_MPI
  // Rank 0 collects every rank's value (so it can name one that does not answer), then tells them the maximum.
  MPI_Request request;
  if (rank_ == 0) {
    for (uint32_t r = 1; r < size_; ++r) {
      int theirs = 0;
      MPI_Irecv(&theirs, 1, MPI_INT, int(r), 5, MPI_COMM_WORLD, &request);
      waitFor(request, int(r), "agreeing on the next step", *this);
      result = std::max(result, theirs);
    }
  } else {
    MPI_Isend(&mine, 1, MPI_INT, 0, 5, MPI_COMM_WORLD, &request);
    waitFor(request, 0, "agreeing on the next step", *this);
  }
  MPI_Ibcast(&result, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
  waitFor(request, rank_ == 0 ? -1 : 0, "agreeing on the next step", *this);
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
