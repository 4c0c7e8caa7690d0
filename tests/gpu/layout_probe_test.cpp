// The GLSL side of every host <-> GPU encoding: shaders/probes/layout_probe.comp reads, by field name, structs the
// host filled with a pattern, and decodes the scene texels GpuScene wrote with the shared functions. A field
// whose std430 offset differs from the C++ one, a texel format that differs, or an encoding that the two
// languages compile differently fails here.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstring>
#include <random>

#include "bvh/bvh.h"
#include "bvh_layout.h"
#include "layout.h"
#include "render/gpu_scene.h"
#include "support/render_helpers.h"
#include "scene_layout.h"
#include "spirv/layout_probe_spv.h"

using namespace vkmc;

namespace {

constexpr uint32_t kSpecEchoStructs = 100;  // layout_probe.comp's constant_id

// Words in the order the probe writes them.
struct Words {
  std::vector<uint32_t> w;
  void put(uint32_t v) { w.push_back(v); }
  void putf(float v) { put(std::bit_cast<uint32_t>(v)); }
  void put3(glm::vec3 v) { putf(v.x), putf(v.y), putf(v.z); }
  void put4(glm::vec4 v) { putf(v.x), putf(v.y), putf(v.z), putf(v.w); }
  void put4u(glm::uvec4 v) { put(v.x), put(v.y), put(v.z), put(v.w); }
};

// Every 4-byte word a distinct float (first, first + 1, ...): a field read at another offset reads another value.
template <typename T>
T patterned(float first) {
  static_assert(sizeof(T) % 4 == 0);
  std::array<float, sizeof(T) / 4> words;
  for (size_t i = 0; i < words.size(); ++i) words[i] = first + float(i);
  return std::bit_cast<T>(words);
}

// The probe's echo, field by field, from the C++ view of the same bytes.
Words echoedByName(const gpu::PathState& p, const gpu::ShadowRay& r, const gpu::Material& m, const gpu::FilmPixel& f,
                   const gpu::Control& c, const gpu::PushConstants& pc) {
  Words e;
  e.put4(p.origin), e.put4(p.direction), e.put4(p.throughput), e.put4(p.radiance);
  e.put(p.pixel), e.put(p.rngKey), e.put(p.depth), e.put(p.rootPath);
  e.put4(r.origin), e.put4(r.direction), e.put4(r.contribution);
  e.put4(m.baseColor), e.put3(m.emission), e.put(m.flags);
  e.putf(m.metallic), e.putf(m.roughness), e.putf(m.specular), e.putf(m.alphaCutoff);
  auto putSlot = [&e](const gpu::TextureSlot& t) {
    e.put4(t.uvRow0), e.put4(t.uvRow1);
    e.put(t.texture), e.put(t.texCoord), e.put(t.unusedSlot0), e.put(t.unusedSlot1);
  };
  for (const gpu::TextureSlot* t : {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture, &m.emissiveTexture})
    putSlot(*t);
  e.put4(m.specularColor), e.put4(m.attenuation), e.put4(m.sheen);
  e.putf(m.clearcoat), e.putf(m.clearcoatRoughness), e.put(m.volumetric), e.put(m.unusedMaterial0);
  for (const gpu::TextureSlot* t :
       {&m.transmissionTexture, &m.clearcoatTexture, &m.clearcoatRoughnessTexture, &m.clearcoatNormalTexture,
        &m.sheenColorTexture, &m.sheenRoughnessTexture, &m.specularTexture, &m.specularColorTexture})
    putSlot(*t);
  e.put4(m.iridescence), putSlot(m.iridescenceTexture), putSlot(m.iridescenceThicknessTexture);
  e.put4(m.anisotropy), putSlot(m.anisotropyTexture), e.put4(m.dispersion);
  e.put4(f.sum), e.put4(f.sumSq), e.put4(f.sumHigh), e.put4(f.sumSqHigh);
  for (const glm::vec4& r : f.replicate) e.put4(r);
  e.put(c.rayQueueCount[0]), e.put(c.rayQueueCount[1]), e.put(c.shadowQueueCount), e.put(c.splitChildren);
  e.put4u(c.rayArgs), e.put4u(c.shadowArgs), e.put4u(c.accumulateArgs);
  e.put(c.cameraRays), e.put(c.extensionRays), e.put(c.shadowRays), e.put(c.copyQueueCount);
  e.put(c.nonfiniteEmission), e.put(c.nonfiniteLightSamples), e.put(c.nonfiniteThroughput), e.put(c.walksCut);
  e.put4u(c.deepArgs);
  e.put(c.deepWalksDeferred), e.put(c.deepWalksTraced), e.put(c.extraShadowRays), e.put(c.splitsRefused);
  e.put(c.walkIterations), e.put(c.walkNodeSteps), e.put(c.walkTriangleTests), e.put(c.walkSlowestLaneIterations);
  e.put4u(c.copyArgs);
  e.put(pc.pathCount), e.put(pc.firstPixel), e.put(pc.sampleIndex), e.put(pc.bounce);
  e.put(pc.width), e.put(pc.height), e.put(pc.seed), e.put(pc.queueCapacity);
  e.put4(pc.cameraOrigin), e.put4(pc.cameraForward), e.put4(pc.cameraRight), e.put4(pc.cameraUp), e.put4(pc.background);
  e.put(pc.pixelCount), e.put(pc.samplesPerPass), e.put(pc.earsTrains), e.put(pc.sampleRuns);
  return e;
}

// Random triangles with random (also downward) vertex normals, every fifth emissive with its own power.
Scene probeScene() {
  Scene s;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int k = 0; k < 4; ++k) {
    Material m;
    m.baseColor = glm::vec3(0.2f * float(k + 1));
    if (k > 1) m.emission = glm::vec3(float(k), 1.0f, 0.5f);
    s.materials.push_back(m);
  }
  for (uint32_t t = 0; t < 60; ++t) {
    for (int k = 0; k < 3; ++k) {
      glm::vec3 p(u(rng), u(rng), u(rng));
      s.positions.push_back(p);
      s.normals.push_back(glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.0f, 0.0f, 1e-3f)));
      s.bounds.grow(p);
    }
    s.materialIds.push_back(t % 5 == 0 ? 2u + t % 2u : t % 2u);
  }
  return s;
}

struct Probe {
  vk::Context& ctx = test::sharedContext();
  Scene scene = probeScene();
  Bvh bvh = buildBvh(scene.triangleBounds());
  GpuScene gpuScene{ctx, scene, bvh};
  vk::KernelLayout layout{ctx};
  vk::Buffer out{ctx, 1u << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible};
  vk::Buffer placeholder{ctx, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal};
  test::RendererTexelPlaceholders texelPlaceholders{ctx, layout};  // a test rebinds the ones it reads
  Probe() {
    test::bindPlaceholders(layout, placeholder, {});
    gpuScene.bindTo(layout);
    layout.bindStorage(BINDING_TEST_HITS, out);
  }
  std::vector<uint32_t> run(bool echo, const gpu::PushConstants& pc, size_t words) {
    vk::Kernel kernel(ctx, layout, "layout_probe", kSpirv_layout_probe,
                      {{SPEC_WORKGROUP_SIZE, gpu::kWorkgroupSize}, {kSpecEchoStructs, echo ? 1u : 0u}});
    std::memset(out.mapped(), 0, out.size());
    ctx.runCommands([&](VkCommandBuffer cmd) { vk::dispatch(cmd, layout, kernel, &pc, sizeof(pc), 1); });
    std::vector<uint32_t> w(words);
    std::memcpy(w.data(), out.mapped(), words * 4);
    return w;
  }
};

template <typename T>
vk::Buffer bufferHolding(vk::Context& ctx, const T& value, uint32_t texelBinding = 0) {
  vk::Buffer b(ctx, sizeof(T), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | (texelBinding ? VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT : 0),
               vk::MemoryKind::HostVisible);
  std::memcpy(b.mapped(), &value, sizeof(T));
  if (texelBinding) b.createView(sceneTexelFormat(texelBinding));
  return b;
}

template <typename T>
std::vector<T> downloaded(const vk::Buffer& b) {
  std::vector<T> v(b.size() / sizeof(T));
  const_cast<vk::Buffer&>(b).download(v.data(), v.size() * sizeof(T));
  return v;
}

}  // namespace

TEST(LayoutProbe, GlslReadsEveryStructFieldAtItsCppOffset) {
  Probe probe;
  auto path = patterned<gpu::PathState>(1000.0f);
  auto ray = patterned<gpu::ShadowRay>(2000.0f);
  auto material = patterned<gpu::Material>(3000.0f);
  auto pixel = patterned<gpu::FilmPixel>(4000.0f);
  auto control = patterned<gpu::Control>(5000.0f);
  auto pc = patterned<gpu::PushConstants>(6000.0f);
  // Paths, shadow rays and materials are read through their texel views (common.glsl loadPath ...).
  // Two slots each: the probe stores slot 0's path, shadow ray and film pixel into slot 1 (and the hits into slots 2, 3).
  vk::Buffer paths = bufferHolding(probe.ctx, std::array<gpu::PathState, 2>{path, {}}, BINDING_PATH_TEXELS),
             rays = bufferHolding(probe.ctx, std::array<gpu::ShadowRay, 2>{ray, {}}, BINDING_SHADOW_TEXELS),
             materials = bufferHolding(probe.ctx, material, BINDING_MATERIALS),
             film = bufferHolding(probe.ctx, std::array<gpu::FilmPixel, 2>{pixel, {}}),
             controlBuffer = bufferHolding(probe.ctx, control);
  probe.layout.bindTexel(BINDING_PATH_TEXELS, paths);
  probe.layout.bindTexel(BINDING_SHADOW_TEXELS, rays);
  probe.layout.bindTexel(BINDING_MATERIALS, materials);
  probe.layout.bindStorage(BINDING_FILM, film);
  probe.layout.bindStorage(BINDING_CONTROL, controlBuffer);
  // Hit w words are a triangle index's bits (a denormal float) or kMissPrimitive (a NaN): read through the texel
  // view, they must come back bit for bit.
  const std::array<glm::uvec4, 2> hitWords{
      glm::uvec4(std::bit_cast<uint32_t>(0.25f), std::bit_cast<uint32_t>(0.5f), std::bit_cast<uint32_t>(0.125f), 5u),
      glm::uvec4(0u, 0u, 0u, gpu::kMissPrimitive)};
  vk::Buffer hits = bufferHolding(probe.ctx, std::array<glm::uvec4, 4>{hitWords[0], hitWords[1], {}, {}}, BINDING_HIT_TEXELS);
  probe.layout.bindTexel(BINDING_HIT_TEXELS, hits);
  probe.layout.bindStorage(BINDING_PATHS, paths);  // the stores go through the storage views of the same buffers
  probe.layout.bindStorage(BINDING_SHADOW_QUEUE, rays);
  probe.layout.bindStorage(BINDING_HITS, hits);
  Words expected = echoedByName(path, ray, material, pixel, control, pc);
  for (const glm::uvec4& h : hitWords) expected.put4u(h);
  // Every word of every struct is echoed once: no field is left out of the comparison.
  ASSERT_EQ(expected.w.size() * 4,
            sizeof(path) + sizeof(ray) + sizeof(material) + sizeof(pixel) + sizeof(control) + sizeof(pc) + sizeof(hitWords));
  std::vector<uint32_t> got = probe.run(true, pc, expected.w.size());
  for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], expected.w[i]) << "echoed word " << i;
  // The stores wrote the same bytes the C++ structs hold (every field's bits, NaN and denormal hit words too).
  auto storedPaths = downloaded<gpu::PathState>(paths);
  auto storedRays = downloaded<gpu::ShadowRay>(rays);
  auto storedHits = downloaded<glm::uvec4>(hits);
  EXPECT_EQ(std::memcmp(&storedPaths[1], &path, sizeof(path)), 0) << "storePath";
  EXPECT_EQ(std::memcmp(&storedRays[1], &ray, sizeof(ray)), 0) << "storeShadowRay";
  auto storedFilm = downloaded<gpu::FilmPixel>(film);
  EXPECT_EQ(std::memcmp(&storedFilm[1], &pixel, sizeof(pixel)), 0) << "storeFilmPixel";
  EXPECT_EQ(storedHits[2], hitWords[0]) << "storeHit";
  EXPECT_EQ(storedHits[3], hitWords[1]) << "storeHit of a miss";
}

TEST(LayoutProbe, GlslDecodesTheSceneTexelsAsTheHostEncodedThem) {
  Probe probe;
  const Scene& scene = probe.scene;
  const uint32_t triangles = uint32_t(scene.triangleCount()), picks = 97, nodes = uint32_t(probe.bvh.wideNodes.size()),
                 leafEntries = 64;
  gpu::PushConstants pc{};
  pc.pathCount = triangles, pc.pixelCount = picks, pc.width = nodes, pc.height = leafEntries;
  const size_t words = triangles * 23 + picks * 2 + nodes * 42 + leafEntries * 4;
  std::vector<uint32_t> got = probe.run(false, pc, words);
  // The host's view of the same texels, decoded with the C++ build of the same functions.
  auto triTexels = downloaded<glm::vec4>(probe.gpuScene.triangles());
  auto infoTexels = downloaded<glm::uvec4>(probe.gpuScene.triangleInfo());
  auto lightTexels = downloaded<glm::uvec4>(probe.gpuScene.lights());
  size_t at = 0;
  auto next = [&] { return got[at++]; };
  auto nextf = [&] { return std::bit_cast<float>(got[at++]); };
  double pmfTotal = 0.0;
  std::vector<float> pmfOf(triangles);
  for (uint32_t t = 0; t < triangles; ++t) {
    const uint32_t src = probe.bvh.triangleOrder[t];
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) EXPECT_EQ(nextf(), scene.positions[3 * src + k][a]) << "triangle " << t;
    pmfOf[t] = nextf();
    EXPECT_EQ(pmfOf[t], triTexels[gpu::kTriangleTexels * t + gpu::kTriangleLightPmfTexel].w);
    EXPECT_EQ(pmfOf[t] > 0.0f, scene.materials[scene.materialIds[src]].isEmissive()) << "triangle " << t;
    pmfTotal += pmfOf[t];
    EXPECT_EQ(next(), scene.materialIds[src]);
    for (int k = 0; k < 3; ++k) {
      glm::vec3 host = gpu::decodeOctahedral(infoTexels[t][k]), device;
      for (int a = 0; a < 3; ++a) device[a] = nextf();
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(device[a], host[a], 1e-6f) << "normal " << k << " of triangle " << t;
      EXPECT_GT(glm::dot(device, scene.normals[3 * src + k]), 0.99999f) << "16-bit octahedral normal of triangle " << t;
      // Re-encoding a decoded normal: the same bits up to one snorm step per component (rounding of ties).
      glm::ivec2 d = glm::ivec2(glm::unpackSnorm2x16(next()) * 32767.0f) -
                     glm::ivec2(glm::unpackSnorm2x16(gpu::encodeOctahedral(host)) * 32767.0f);
      EXPECT_LE(std::max(std::abs(d.x), std::abs(d.y)), 1) << "normal " << k << " of triangle " << t;
    }
  }
  EXPECT_NEAR(pmfTotal, 1.0, 1e-5);
  const uint32_t lights = uint32_t(lightTexels.size());
  for (uint32_t k = 0; k < picks; ++k) {
    float scaled = (float(k) + 0.5f) / float(picks) * float(lights);
    uint32_t slot = gpu::aliasSlot(scaled, lights);
    glm::uvec4 chosen = lightTexels[gpu::aliasChoice(scaled, slot, lightTexels[slot])];
    uint32_t tri = next();
    EXPECT_EQ(tri, gpu::lightEntryIndex(chosen)) << "light pick " << k;
    EXPECT_EQ(nextf(), gpu::lightEntryPmf(chosen)) << "light pick " << k;
    ASSERT_LT(tri, triangles);
    // An emitter quad's entry names its first half and carries the pair's pmf, twice each half's.
    const bool quad = gpu::hasEmitterPartner(triTexels[gpu::kTriangleTexels * tri + gpu::kTrianglePartnerTexel].w);
    EXPECT_EQ(gpu::lightEntryPmf(chosen), pmfOf[tri] * (quad ? 2.0f : 1.0f)) << "the entry's pmf is its triangle's";
  }
  for (uint32_t n = 0; n < nodes; ++n) {
    const BvhWideNode& node = probe.bvh.wideNodes[n];
    const glm::uvec4 grid = node.texels[gpu::kBvhWideGridTexel];
    for (int a = 0; a < 3; ++a) EXPECT_EQ(next(), grid[a]) << "origin of node " << n;
    glm::vec3 step = gpu::bvhWideStep(grid.w);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(nextf(), step[a]) << "step of node " << n;
    for (uint32_t axis = 0; axis < 3; ++axis) {
      glm::uvec2 planes =
          gpu::bvhWidePlaneWords(node.texels[gpu::kBvhWideXyPlanesTexel], node.texels[gpu::kBvhWideZPlanesTexel], axis);
      for (uint32_t word : {planes.x, planes.y})
        for (int c = 0; c < 4; ++c) EXPECT_EQ(next(), gpu::bvhWidePlaneSteps(word)[c]) << "planes of node " << n;
    }
    for (int c = 0; c < 4; ++c) {
      uint32_t e = node.texels[gpu::kBvhWideChildTexel][c];
      bool leaf = e != gpu::kBvhEmptySlot && gpu::bvhIsLeaf(e);
      EXPECT_EQ(next(), leaf ? 1u : 0u) << "child " << c << " of node " << n;
      EXPECT_EQ(next(), leaf ? gpu::bvhLeafFirst(e) : e);
      EXPECT_EQ(next(), leaf ? gpu::bvhLeafCount(e) : 0u);
    }
  }
  for (uint32_t i = 0; i < leafEntries; ++i) {
    uint32_t first = (i * 2654435761u) % gpu::kBvhLeafFirstLimit, count = 1u + i % gpu::kBvhMaxLeafSize;
    EXPECT_EQ(next(), gpu::bvhLeafEntry(first, count));
    EXPECT_EQ(next(), first);
    EXPECT_EQ(next(), count);
    EXPECT_EQ(next(), 1u);
  }
  EXPECT_EQ(at, words);
}

TEST(LayoutProbe, SceneTexelFormatsComeFromTheGlslDeclarations) {
  EXPECT_EQ(sceneTexelFormat(BINDING_TRIANGLES), VK_FORMAT_R32G32B32A32_SFLOAT);
  for (uint32_t b : {BINDING_TRIANGLE_INFO, BINDING_BVH_NODES, BINDING_LIGHTS})
    EXPECT_EQ(sceneTexelFormat(b), VK_FORMAT_R32G32B32A32_UINT) << "binding " << b;
}
