// The shared sampling functions give the same answers on the device as in the C++ build: spherical-triangle
// sampling and the solid angle, for a small and a near-hemispherical triangle (GLSL's transcendental functions
// have looser precision than C++'s; these uses must not depend on it).
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "../shaders/shared/layout.h"
#include "../shaders/shared/light_sampling.h"
#include "../shaders/shared/rng.h"
#include "spirv/sampling_probe_spv.h"
#include "support/render_helpers.h"
#include "support/z_test.h"
#include "vk/kernel.h"

using namespace vkmc;

namespace {
struct Triangle {
  glm::vec3 p, a, b, c;
  const char* name;
};
void PrintTo(const Triangle& t, std::ostream* os) { *os << t.name; }

constexpr uint32_t kSamples = 1u << 20;

// The probe kernel and its output buffer, built once for both rows.
class GpuSampling : public ::testing::TestWithParam<Triangle> {
 protected:
  struct Probe {
    vk::Context ctx;
    vk::KernelLayout layout{ctx};
    vk::Buffer dummy{ctx, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal};
    vk::Buffer out{ctx, kSamples * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible};
    std::unique_ptr<vk::Kernel> kernel;
    Probe() {
      test::bindPlaceholders(layout, dummy, {BINDING_TEST_HITS});
      layout.bindStorage(BINDING_TEST_HITS, out);
      kernel = std::make_unique<vk::Kernel>(ctx, layout, "sampling_probe", kSpirv_sampling_probe,
                                            std::vector<vk::SpecConstant>{{SPEC_WORKGROUP_SIZE, gpu::kWorkgroupSize}});
    }
  };
  static void SetUpTestSuite() { probe = new Probe(); }
  static void TearDownTestSuite() {
    delete probe;
    probe = nullptr;
  }
  static Probe* probe;
};
GpuSampling::Probe* GpuSampling::probe = nullptr;
}  // namespace

TEST_P(GpuSampling, SphericalTriangleSamplingMatchesTheHost) {
  const uint32_t n = kSamples;
  const Triangle t = GetParam();
  vk::Context& ctx = probe->ctx;
  gpu::PushConstants pc{};
  pc.pathCount = n;
  pc.seed = 77;
  pc.cameraOrigin = glm::vec4(t.p, 0);
  pc.cameraForward = glm::vec4(t.a, 0);
  pc.cameraRight = glm::vec4(t.b, 0);
  pc.cameraUp = glm::vec4(t.c, 0);
  ctx.runCommands(
      [&](VkCommandBuffer cmd) { vk::dispatch(cmd, probe->layout, *probe->kernel, &pc, sizeof(pc), n / gpu::kWorkgroupSize); });
  std::vector<glm::vec4> r(n);
  std::memcpy(r.data(), probe->out.mapped(), n * 16);
  glm::vec3 nrm = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
  float hostOmega = gpu::triangleSolidAngle(t.p, t.a, t.b, t.c);
  // Vulkan lets atan be off by thousands of ulps (llvmpipe measured ~1e-5 relative): 1e-3 is that allowance.
  EXPECT_NEAR(r[0].w, hostOmega, 1e-3f * hostOmega) << t.name << ": solid angle";
  // Mean cosine to the triangle's normal over the samples, device against host (same random numbers).
  double gpuCos = 0, hostSum = 0, hostSq = 0;
  for (uint32_t i = 0; i < n; ++i) {
    gpuCos += std::abs(glm::dot(glm::vec3(r[i]), nrm));
    uint32_t key = gpu::pathKey(77u, i, 0u);
    glm::vec3 w =
        gpu::sampleSphericalTriangle(t.p, t.a, t.b, t.c, glm::vec2(gpu::randomUnit(key, 0), gpu::randomUnit(key, 1)), hostOmega);
    double c = std::abs(glm::dot(w, nrm));
    hostSum += c;
    hostSq += c * c;
  }
  gpuCos /= n;
  test::SampleMean hostCos = test::sampleMean(hostSum, hostSq, n);
  EXPECT_TRUE(test::withinSigmas(test::zTest(gpuCos, hostCos.mean, hostCos.sigma, 1e-5), 5)) << t.name << ": mean cosine";
}

INSTANTIATE_TEST_SUITE_P(SmallAndWide, GpuSampling,
                         ::testing::Values(Triangle{glm::vec3(0), glm::vec3(-0.3f, -0.2f, 2.0f), glm::vec3(0.4f, -0.1f, 2.2f),
                                                    glm::vec3(0.0f, 0.5f, 1.8f), "small"},
                                           Triangle{glm::vec3(0, 0, -0.02f), glm::vec3(-10, 0.05f, -10),
                                                    glm::vec3(10, 0.05f, -10), glm::vec3(10, 0.05f, 10), "near_hemispherical"}),
                         [](const auto& info) { return std::string(info.param.name); });
