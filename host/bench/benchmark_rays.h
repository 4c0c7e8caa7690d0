// The traversal benchmark's rays, made the same way for vkmc's own kernel and for external baselines (Embree):
// camera rays through pixel centres (coherent), then four cosine-distributed bounce rays about the geometric
// normal at each of their hits (incoherent, as in a diffuse bounce), offset as the renderer offsets them.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "../shaders/shared/layout.h"
#include "bvh/bvh.h"
#include "scene/scene.h"

namespace vkmc {

class RayTracer;

struct BenchmarkRays {
  std::vector<gpu::TestRay> primary, diffuse;
};

// Primary hits come from `tracer` (the GPU traversal); `bvh` maps its triangle order back to the scene's.
BenchmarkRays makeBenchmarkRays(const Scene& scene, const Bvh& bvh, RayTracer& tracer, uint32_t width, uint32_t height);

// Binary dump: "VKMCRAYS", uint32 count, then count TestRay records (origin.xyz, tmax, direction.xyz, 0).
void writeRays(const std::string& path, const std::vector<gpu::TestRay>& rays);
std::vector<gpu::TestRay> readRays(const std::string& path);

}  // namespace vkmc
