// Scene report: features, kernels with their specialization constants, triangles, BVH, memory, warnings.
#include "app/info.h"

#include <bit>
#include <cstdio>

#include "../shaders/shared/layout.h"
#include "app/malloc_tuning.h"
#include "bvh/bvh.h"
#include "estimators/estimator_params.h"
#include "policy/estimator_choice.h"
#include "render/gpu_scene.h"
#include "render/path_renderer.h"
#include "render/render_kernels.h"
#include "scene/framing.h"
#include "scene/camera_rig.h"
#include "scene/gltf_loader.h"
#include "scene/scene_features.h"

namespace vkmc {
namespace {
// Estimator constants are named by their key; the rest are the scene's and the renderer's own.
const char* specName(uint32_t id) {
  switch (id) {
    case SPEC_WORKGROUP_SIZE: return "workgroup_size";
    case SPEC_HAS_LIGHTS: return "has_lights";
    case SPEC_HAS_GLOSSY: return "has_glossy";
    case SPEC_HAS_TEXTURES: return "has_textures";
    case SPEC_HAS_NORMAL_MAPS: return "has_normal_maps";
    case SPEC_HAS_ALPHA: return "has_alpha";
    case SPEC_CULLS_BACK_FACES: return "culls_back_faces";
    case SPEC_HAS_TRANSMISSION: return "has_transmission";
    case SPEC_HAS_CLEARCOAT: return "has_clearcoat";
    case SPEC_HAS_SHEEN: return "has_sheen";
    case SPEC_HAS_IRIDESCENCE: return "has_iridescence";
    case SPEC_HAS_ANISOTROPY: return "has_anisotropy";
    case SPEC_HAS_DISPERSION: return "has_dispersion";
    case SPEC_HAS_DELTA: return "has_delta";
    case SPEC_HAS_PUNCTUAL: return "has_punctual";
    case SPEC_HAS_ENVIRONMENT: return "has_environment";
    case SPEC_RR_MODE: return "rr_mode";  // the key rr, named as info has always shown it
    case SPEC_RECORD_DEPTH_STATS: return "record_depth_stats";
    case SPEC_SAMPLER_LOG2_SPP: return "zsobol_log2_spp";
    case SPEC_SAMPLER_DIGITS: return "zsobol_digits";
    case SPEC_DEEP_WALKS: return "deep_walks";
    case SPEC_REGISTER_STACK: return "register_stack";
    case SPEC_PIXEL_FILTER: return "pixel_filter";  // 0: the pixel's box (u as is), 1: a filter's table
  }
  for (const EstimatorParam& p : estimatorParams())
    if (p.specId == int(id)) return p.key;
  return "?";
}

bool isFloatSpec(uint32_t id) {
  for (const EstimatorParam& p : estimatorParams())
    if (p.specId == int(id)) return p.kind == ParamKind::Real;
  return false;
}

// What `vkmc render` would choose between on this scene, in two lines (estimator_choice.h).
void printEstimatorChoice(const vk::Context& ctx, const SceneFeatures& f) {
  std::string keys;
  for (const SearchStep& step :
       estimatorSearchSteps({}, SearchScene{f.lights(), ctx.hasFloatAtomics(), f.glossy, f.emitters()})) {
    const EstimatorParam* p = findEstimatorParam(step.key);
    for (double v : step.values) keys += (keys.empty() ? "" : ", ") + step.key + " " + p->text(v);
  }
  std::printf(
      "estimator    chosen by vkmc render: short pilots (at most 5%% of the render) measure the defaults against\n"
      "             %s; --estimator defaults renders the defaults unmeasured\n",
      keys.empty() ? "nothing (no key changes this scene)" : keys.c_str());
}
}  // namespace

int runInfo(const RenderOptions& options) {
  vk::Context ctx;
  Scene scene = loadGltf(options.scenePath, deviceLoadLimits(ctx));
  SceneFeatures f = scanFeatures(scene);
  const AddedLight added = addedLight(options, scene);
  f.environment = added != AddedLight::None;
  std::printf("scene        %s\n", options.scenePath.c_str());
  std::printf("triangles    %u (%s), %llu zero-area skipped, %u materials, %zu cameras\n", f.triangles, f.sizeClass(),
              static_cast<unsigned long long>(scene.degenerateTriangles), f.materials, scene.cameras.size());
  if (!scene.thinSegments.empty())
    std::printf("lines        %zu point and line segments (a render draws each as a 2-triangle ribbon one pixel wide)\n",
                scene.thinSegments.size());
  std::printf(
      "features     emitters %s (%u emissive triangles), glossy %s, metallic %s, non-default specular %s,\n"
      "             double-sided %s, single-sided %s, textures %s (%zu), normal maps %s, alpha %s,\n"
      "             transmission %s (volumes %s, dispersion %s), clearcoat %s, sheen %s, iridescence %s,\n"
      "             anisotropy %s, smooth (delta) lobes %s, punctual lights %u, environment %s\n",
      f.emitters() ? "yes" : "no", f.emissiveTriangles, f.glossy ? "yes" : "no", f.metallic ? "yes" : "no",
      f.nonDefaultSpecular ? "yes" : "no", f.doubleSided ? "yes" : "no", f.singleSided ? "yes" : "no", f.textures ? "yes" : "no",
      scene.textures.size(), f.normalMaps ? "yes" : "no", f.alpha ? "yes" : "no", f.transmission ? "yes" : "no",
      f.volumes ? "yes" : "no", f.dispersion ? "yes" : "no", f.clearcoat ? "yes" : "no", f.sheen ? "yes" : "no",
      f.iridescence ? "yes" : "no", f.anisotropy ? "yes" : "no", f.delta ? "yes" : "no", f.punctualLights,
      added == AddedLight::Map      ? options.environmentPath.c_str()
      : added == AddedLight::Studio ? "studio (the file declares no other world)"
      : added == AddedLight::White  ? "constant (the file's white world)"
                                    : "none (the file's lights-only world)");
  std::vector<Aabb> bounds = scene.triangleBounds();
  Bvh bvh = buildBvh(bounds);
  const BvhStats& b = bvh.stats;
  std::printf(
      "bvh          %u inner nodes, %u leaves, depth %u (4-wide %u, at most %u entries pending: register stack of %u, %s), "
      "leaf size avg %.2f max %u, SAH cost %.2f (4-wide %.2f), built in %.3f s on %u threads\n",
      b.innerNodes, b.leaves, b.maxDepth, b.wideMaxDepth, b.wideMaxPending, registerStackEntries(b),
      walksCanOutgrowRegisterStack(b) ? "deep passes built" : "no walk outgrows it", b.averageLeafSize, b.maxLeafSize, b.sahCost,
      b.wideSahCost, b.buildSeconds, b.buildThreads);
  GpuScene gpu(ctx, scene, bvh, options.estimator.lightSelect == LightSelect::Uniform);
  RenderSettings settings;
  settings.estimator = options.estimator;
  settings.features = pipelineFeatures(f, bvh.stats, options.specialize);
  settings.width = options.width.value_or(256);
  settings.height = options.height.value_or(256);
  settings.spp = options.spp;
  Camera cam = scene.cameras.empty() ? autoCamera(framingBounds(scene).bounds, 1.0f) : scene.cameras[0];
  settings.camera = makeCameraRig(cam, settings.width, settings.height);
  printEstimatorChoice(ctx, settings.features);
  KernelPlan plan = planKernels(settings);
  const std::string spirv = plan.spirvVariant.empty() ? "general SPIR-V" : "SPIR-V pre-specialized for " + plan.spirvVariant;
  std::printf("kernels      %s pipelines on %s, %s:\n", options.specialize ? "specialized" : "general", ctx.deviceName().c_str(),
              spirv.c_str());
  for (const std::string& k : plan.kernels) std::printf("               %s\n", k.c_str());
  std::printf("              not dispatched: %s\n",
              plan.kernels.size() < 7 ? "prepare_shadow, shadow (no lights or NEE off)" : "none");
  std::printf("spec consts  ");
  int n = 0;
  for (const vk::SpecConstant& s : plan.specs) {
    const char* sep = n == 0 ? "" : (n % 5 == 0 ? "\n              " : ", ");
    if (isFloatSpec(s.id))
      std::printf("%s%s=%g", sep, specName(s.id), std::bit_cast<float>(s.value));
    else
      std::printf("%s%s=%u", sep, specName(s.id), s.value);
    ++n;
  }
  std::printf("\n");
  PathRenderer renderer(ctx, gpu, settings);
  std::printf("memory       scene buffers:");
  uint64_t total = 0;
  for (const auto& [name, bytes] : gpu.info().bufferBytes) {
    std::printf(" %s %.1f KiB,", name.c_str(), bytes / 1024.0);
    total += bytes;
  }
  std::printf("\n              render buffers (%ux%u): %.2f MiB; total %.2f MiB\n", settings.width, settings.height,
              renderer.deviceBytes() / 1048576.0, (total + renderer.deviceBytes()) / 1048576.0);
  const std::string& tunables = mallocTunablesAdded();
  std::printf("malloc       %s\n", tunables.empty()
                                       ? "glibc's defaults (no tunables added: app/malloc_tuning.h says when)"
                                       : ("GLIBC_TUNABLES added " + tunables + " (VKMC_MALLOC_TUNING=off: none)").c_str());
  for (const std::string& w : scene.warnings) std::fprintf(stderr, "vkmc: warning: %s\n", w.c_str());
  for (const std::string& u : f.unsupported()) std::printf("unsupported  %s\n", u.c_str());
  return 0;
}

}  // namespace vkmc
