// Texture decoding and references.
#include "scene/gltf_textures.h"

#include <stb/stb_image.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>

#include "error.h"

namespace vkmc {
namespace {

TextureWrap wrapOf(int mode) {
  switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
    default: return TextureWrap::Repeat;
  }
}

double number(const tinygltf::Value& v, const char* key, double fallback) {
  if (!v.Has(key) || !v.Get(key).IsNumber()) return fallback;
  return v.Get(key).GetNumberAsDouble();
}
bool pair(const tinygltf::Value& v, const char* key, double out[2]) {
  if (!v.Has(key) || !v.Get(key).IsArray() || v.Get(key).ArrayLen() != 2) return false;
  for (int i = 0; i < 2; ++i) {
    if (!v.Get(key).Get(i).IsNumber()) return false;
    out[i] = v.Get(key).Get(i).GetNumberAsDouble();
  }
  return true;
}

// The shared part of both textureInfo kinds: index, texCoord and KHR_texture_transform (spec: uv' = T R S uv, with
// R = [cos sin; -sin cos]; a texCoord inside the extension overrides the textureInfo's).
TextureRef convertRef(int index, int texCoord, const tinygltf::ExtensionMap& extensions, const std::vector<Texture>& textures,
                      const std::string& what, std::vector<std::string>& warnings) {
  TextureRef ref;
  if (index < 0) return ref;
  if (index >= static_cast<int>(textures.size())) throw Error(what + " refers to missing texture " + std::to_string(index));
  if (textures[index].width == 0) return ref;  // undecodable: warned once by convertTextures
  ref.texture = index;
  ref.texCoord = texCoord;
  if (auto it = extensions.find("KHR_texture_transform"); it != extensions.end()) {
    const tinygltf::Value& t = it->second;
    double offset[2] = {0.0, 0.0}, scale[2] = {1.0, 1.0};
    pair(t, "offset", offset);
    pair(t, "scale", scale);
    double rotation = number(t, "rotation", 0.0);
    ref.texCoord = static_cast<int>(number(t, "texCoord", texCoord));
    double c = std::cos(rotation), s = std::sin(rotation);
    ref.uvRow0 = glm::vec3(float(c * scale[0]), float(s * scale[1]), float(offset[0]));
    ref.uvRow1 = glm::vec3(float(-s * scale[0]), float(c * scale[1]), float(offset[1]));
    if (!std::isfinite(rotation) ||
        !std::isfinite(ref.uvRow0.x + ref.uvRow0.y + ref.uvRow0.z + ref.uvRow1.x + ref.uvRow1.y + ref.uvRow1.z))
      throw Error(what + ": KHR_texture_transform is not finite");
  }
  if (ref.texCoord < 0 || ref.texCoord > 1) {
    warnings.push_back(what + " uses TEXCOORD_" + std::to_string(ref.texCoord) + " (only 0 and 1 are read): ignored");
    return TextureRef{};
  }
  return ref;
}

}  // namespace

bool decodeGltfImage(tinygltf::Image* image, const int imageIndex, std::string*, std::string*, int, int,
                     const unsigned char* bytes, int size, void* user) {
  auto* decoder = static_cast<ImageDecoder*>(user);
  std::string label = "image " + std::to_string(imageIndex) + (image->name.empty() ? "" : " (" + image->name + ")");
  int w = 0, h = 0, channels = 0;
  // PNG and JPEG only, by their signatures: stb_image knows more (GIF, BMP, PSD, TGA, Radiance HDR), some of them
  // through decoders that loop on a cut file, and glTF allows these two.
  const bool png = size >= 8 && std::memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0;
  const bool jpeg = size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
  if (bytes && size > 0 && !png && !jpeg) {
    decoder->failures.push_back(label + ": neither PNG nor JPEG (the image formats vkmc reads)" +
                                (image->mimeType.empty() ? "" : " (" + image->mimeType + ")"));
    return true;
  }
  if (!bytes || size <= 0 || !stbi_info_from_memory(bytes, size, &w, &h, &channels)) {
    decoder->failures.push_back(label + ": not a PNG or JPEG stb_image can read" +
                                (image->mimeType.empty() ? "" : " (" + image->mimeType + ")"));
    return true;
  }
  if (w <= 0 || h <= 0 || uint32_t(w) > decoder->limits.maxDimension || uint32_t(h) > decoder->limits.maxDimension) {
    decoder->failures.push_back(label + ": " + std::to_string(w) + "x" + std::to_string(h) + " exceeds " +
                                std::to_string(decoder->limits.maxDimension) + " texels a side");
    return true;
  }
  uint64_t texels = uint64_t(w) * uint64_t(h);
  if (decoder->decodedTexels + texels > decoder->limits.maxTotalTexels) {
    decoder->failures.push_back(label + ": the scene's images exceed " + std::to_string(decoder->limits.maxTotalTexels) +
                                " texels in all");
    return true;
  }
  unsigned char* pixels = stbi_load_from_memory(bytes, size, &w, &h, &channels, 4);
  if (!pixels) {
    decoder->failures.push_back(label + ": " + (stbi_failure_reason() ? stbi_failure_reason() : "decoding failed"));
    return true;
  }
  decoder->decodedTexels += texels;
  image->width = w;
  image->height = h;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image.assign(pixels, pixels + texels * 4);
  stbi_image_free(pixels);
  return true;
}

std::vector<Texture> convertTextures(const tinygltf::Model& model, std::vector<std::string>& warnings) {
  std::vector<Texture> out;
  for (size_t i = 0; i < model.textures.size(); ++i) {
    const tinygltf::Texture& t = model.textures[i];
    Texture tex;
    tex.name = t.name;
    if (t.sampler >= 0 && t.sampler < static_cast<int>(model.samplers.size())) {
      const tinygltf::Sampler& s = model.samplers[t.sampler];
      tex.wrapS = wrapOf(s.wrapS);
      tex.wrapT = wrapOf(s.wrapT);
      tex.nearest = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
    }
    int source = t.source;
    if (source >= 0 && source < static_cast<int>(model.images.size()) && !model.images[source].image.empty() &&
        model.images[source].component == 4 && model.images[source].bits == 8) {
      const tinygltf::Image& img = model.images[source];
      tex.width = static_cast<uint32_t>(img.width);
      tex.height = static_cast<uint32_t>(img.height);
      tex.texels.resize(size_t(tex.width) * tex.height);
      std::memcpy(tex.texels.data(), img.image.data(), tex.texels.size() * 4);
    } else {
      warnings.push_back("texture " + std::to_string(i) + (t.name.empty() ? "" : " (" + t.name + ")") +
                         " has no image vkmc can decode (PNG and JPEG are read): ignored");
    }
    out.push_back(std::move(tex));
  }
  return out;
}

TextureRef convertTextureRef(const tinygltf::TextureInfo& info, const std::vector<Texture>& textures, const std::string& what,
                             std::vector<std::string>& warnings) {
  return convertRef(info.index, info.texCoord, info.extensions, textures, what, warnings);
}

TextureRef convertTextureRef(const tinygltf::NormalTextureInfo& info, const std::vector<Texture>& textures,
                             const std::string& what, std::vector<std::string>& warnings) {
  TextureRef ref = convertRef(info.index, info.texCoord, info.extensions, textures, what, warnings);
  ref.scale = static_cast<float>(info.scale);
  if (!std::isfinite(ref.scale)) throw Error(what + ": scale is not finite");
  return ref;
}

TextureRef convertTextureRef(const tinygltf::Value& info, const std::vector<Texture>& textures, const std::string& what,
                             std::vector<std::string>& warnings) {
  if (!info.IsObject()) throw Error(what + " is not an object");
  const tinygltf::Value& index = info.Get("index");
  if (!index.IsInt()) throw Error(what + " has no integer index");
  int texCoord = info.Has("texCoord") && info.Get("texCoord").IsInt() ? info.Get("texCoord").GetNumberAsInt() : 0;
  tinygltf::ExtensionMap extensions;
  if (info.Has("extensions") && info.Get("extensions").IsObject())
    for (const std::string& key : info.Get("extensions").Keys()) extensions[key] = info.Get("extensions").Get(key);
  TextureRef ref = convertRef(index.GetNumberAsInt(), texCoord, extensions, textures, what, warnings);
  if (info.Has("scale")) {
    const tinygltf::Value& scale = info.Get("scale");
    ref.scale = scale.IsNumber() ? static_cast<float>(scale.GetNumberAsDouble()) : NAN;
    if (!std::isfinite(ref.scale)) throw Error(what + ": scale is not finite");
  }
  return ref;
}

}  // namespace vkmc
