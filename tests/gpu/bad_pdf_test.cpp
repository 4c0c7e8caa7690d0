// The lecture's bad-pdf counterexample, computed by a compute kernel (shaders/probes/pdf_demo.comp): sampling
// by a pdf shaped unlike the integrand keeps the mean but makes the variance far worse than uniform sampling.
// Exact values: uniform variance 0.0099; bad-pdf variance 0.0099 * 101^2 + 0.9901 * (1/9901)^2 - 1 = 99.99.
#include <gtest/gtest.h>

#include <cstring>

#include "../shaders/shared/layout.h"
#include "spirv/pdf_demo_spv.h"
#include "support/render_helpers.h"
#include "support/z_test.h"
#include "vk/kernel.h"

using namespace vkmc;

TEST(BadPdf, PdfShapedUnlikeTheIntegrandRaisesVariance) {
  vk::Context ctx;
  vk::KernelLayout layout(ctx);
  vk::Buffer dummy(ctx, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
  test::bindPlaceholders(layout, dummy, {BINDING_TEST_HITS});
  const uint32_t invocations = 4096, perInvocation = 256;
  vk::Buffer out(ctx, invocations * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
  layout.bindStorage(BINDING_TEST_HITS, out);
  vk::Kernel kernel(ctx, layout, "pdf_demo", kSpirv_pdf_demo, {{SPEC_WORKGROUP_SIZE, gpu::kWorkgroupSize}});
  gpu::PushConstants pc{};
  pc.pathCount = invocations;
  pc.sampleIndex = perInvocation;
  pc.seed = 2024;
  ctx.runCommands(
      [&](VkCommandBuffer cmd) { vk::dispatch(cmd, layout, kernel, &pc, sizeof(pc), invocations / gpu::kWorkgroupSize); });
  std::vector<glm::vec4> sums(invocations);
  std::memcpy(sums.data(), out.mapped(), invocations * 16);
  double n = double(invocations) * perInvocation, bad = 0, badSq = 0, uni = 0, uniSq = 0;
  for (const glm::vec4& s : sums) bad += s.x, badSq += s.y, uni += s.z, uniSq += s.w;
  double meanBad = bad / n, meanUni = uni / n;
  double varBad = badSq / n - meanBad * meanBad, varUni = uniSq / n - meanUni * meanUni;
  EXPECT_TRUE(test::withinSigmas(test::zTest(meanUni, 1.0, std::sqrt(varUni / n)), 5.0)) << "uniform sampling";
  EXPECT_TRUE(test::withinSigmas(test::zTest(meanBad, 1.0, std::sqrt(varBad / n)), 5.0)) << "the bad pdf";
  EXPECT_NEAR(varUni, 0.0099, 0.0099 * 0.05);
  EXPECT_NEAR(varBad, 99.99, 99.99 * 0.1);
  EXPECT_GT(varBad, 1000.0 * varUni);
}
