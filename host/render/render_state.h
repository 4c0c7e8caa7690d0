// What a render has done so far: everything a checkpoint saves and a resumed render continues from, bit for bit.
// The float batch the device has not folded yet is part of it, so a render stopped at any pass boundary resumes
// with the same float additions, in the same order, as one that never stopped.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "../shaders/shared/layout.h"
#include "render/film.h"
#include "render/render_settings.h"

namespace vkmc {

struct RenderState {
  Film film;                          // folded sample batches, in double
  std::vector<gpu::FilmPixel> batch;  // the device's float batch not folded yet (empty: none)
  uint32_t batchSamples = 0;          // samples per pixel in `batch`
  uint32_t nextSample = 0;            // the first sample index not rendered yet
  RenderStats stats;                  // counters and seconds so far (the sample passes only)
  bool interrupted = false;           // stopped by RenderControl::stop before its target
  int stopSignal = 0;                 // what stopped it: the signal's number (under mpirun, any rank's)

  // Every sample done: the film with the unfolded batch added.
  Film image() const {
    Film f = film;
    if (!batch.empty()) f.addBatch(batch.data());
    return f;
  }
};

// How a caller steers a render between passes.
struct RenderControl {
  const std::atomic<int>* stop = nullptr;  // non-zero: stop after the pass in flight (a signal's number)
  double checkpointEvery = 0.0;            // seconds between calls of `checkpoint` (0: never)
  std::function<void(const RenderState&)> checkpoint;
};

}  // namespace vkmc
