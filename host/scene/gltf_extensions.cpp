// The extension table: one row per extension vkmc knows, with what it ignores of it.
#include "scene/gltf_extensions.h"

#include <algorithm>
#include <string_view>

#include "error.h"

namespace vkmc {
namespace {

using ExtensionRow = GltfExtensionSupport;  // ignored empty: implemented in full

constexpr ExtensionRow kExtensions[] = {
    {"KHR_materials_emissive_strength", ""},
    {"KHR_materials_specular", ""},  // factor, colour and textures (scene/gltf_material_extensions.cpp)
    {"KHR_lights_punctual", ""},     // range is ignored (physically based), with a warning
    {"KHR_texture_transform", ""},
    {"KHR_texture_basisu", ""},  // KTX2 transcoded by the vendored Basis Universal (scene/ktx2_decode.cpp)
    {"EXT_texture_webp", ""},    // libwebp (scene/image_decode.cpp); the core source is the fallback
    {"EXT_texture_avif", "AVIF images are not decoded (a texture whose core source is PNG, JPEG, WebP or KTX2 uses that)"},
    {"KHR_materials_transmission", ""},  // bsdf_gltf.h; shadow rays do not pass it (docs/manual/scenes.md)
    {"KHR_materials_volume", ""},        // refraction and Beer-Lambert attenuation; thicknessTexture is not needed
    {"KHR_materials_ior", ""},
    {"KHR_materials_clearcoat", ""},
    {"KHR_materials_sheen", ""},
    {"KHR_materials_iridescence", ""},
    {"KHR_materials_anisotropy", ""},  // anisotropic GGX (microfacet.h) in the tangent frame
    {"KHR_materials_dispersion", ""},  // a colour channel per path past a dispersive volume (scene/dispersion.h)
    {"KHR_materials_diffuse_transmission", "diffuse transmission is ignored"},
    {"KHR_materials_unlit", ""},                  // an emission shader of the base colour (gltf_loader.cpp, makeUnlit)
    {"KHR_materials_pbrSpecularGlossiness", ""},  // converted to metallic-roughness per texel (scene/spec_gloss.h)
    {"KHR_materials_variants", "only each primitive's default material is used"},
    {"KHR_draco_mesh_compression", ""},  // decoded by scene/gltf_decompress (libdraco)
    {"EXT_meshopt_compression", ""},     // decoded by scene/gltf_decompress (libmeshoptimizer)
    {"KHR_mesh_quantization", ""},       // integer attributes read by scene/gltf_accessors
    {"EXT_mesh_gpu_instancing", ""},     // every instance drawn; counted by the instancing-bomb guard
    {"KHR_animation_pointer", "animations are ignored (vkmc renders the rest pose)"},
    {"KHR_xmp_json_ld", "metadata is ignored"},
};

const ExtensionRow* find(const std::string& name) {
  for (const ExtensionRow& row : kExtensions)
    if (row.name == name) return &row;
  return nullptr;
}

}  // namespace

std::span<const GltfExtensionSupport> knownExtensions() { return kExtensions; }

std::vector<std::string> checkExtensions(const std::vector<std::string>& used, const std::vector<std::string>& required) {
  for (const std::string& name : required) {
    const ExtensionRow* row = find(name);
    if (!row) throw Error("the file requires extension " + name + ", which vkmc does not know");
    if (!row->ignored.empty())
      // The row says what a file that only uses it loses; a file that requires it is refused, so say that.
      throw Error("the file requires extension " + name + ", which vkmc does not implement in full (" +
                  std::string(row->ignored) + "), so it cannot render the file as required");
  }
  std::vector<std::string> names = used;
  for (const std::string& name : required)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  std::vector<std::string> warnings;
  for (const std::string& name : names) {
    const ExtensionRow* row = find(name);
    if (!row)
      warnings.push_back("extension " + name + " is unknown to vkmc and ignored");
    else if (!row->ignored.empty())
      warnings.push_back("extension " + name + ": " + std::string(row->ignored));
  }
  return warnings;
}

}  // namespace vkmc
