// Texture decoding and references.
#include "scene/gltf_textures.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>

#include "error.h"
#include "scene/image_decode.h"

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

// A texture's image sources, preferred first: EXT_texture_webp's, KHR_texture_basisu's, then the core `source`
// (the extensions' fallback, as their specs say).
std::vector<int> sourcesOf(const tinygltf::Texture& t) {
  std::vector<int> sources;
  for (const char* extension : {"EXT_texture_webp", "KHR_texture_basisu"}) {
    auto it = t.extensions.find(extension);
    if (it != t.extensions.end() && it->second.IsObject() && it->second.Get("source").IsInt())
      sources.push_back(it->second.Get("source").GetNumberAsInt());
  }
  if (t.source >= 0) sources.push_back(t.source);
  return sources;
}

bool decoded(const std::vector<tinygltf::Image>& images, int source) {
  return source >= 0 && source < static_cast<int>(images.size()) && !images[source].image.empty() &&
         images[source].component == 4 && images[source].bits == 8;
}

int chosenSource(const tinygltf::Texture& t, const std::vector<tinygltf::Image>& images) {
  for (int source : sourcesOf(t))
    if (decoded(images, source)) return source;
  return -1;
}

// Names what a texture without a decoded image pointed at: each image by index and file, the common cause being
// a missing file (the decoder's own reason is in the image warnings).
std::string sourcesTried(const tinygltf::Texture& t, const std::vector<tinygltf::Image>& images) {
  std::string tried;
  for (int source : sourcesOf(t)) {
    tried += tried.empty() ? "" : ", ";
    if (source < 0 || source >= static_cast<int>(images.size())) {
      tried += "image " + std::to_string(source) + " does not exist";
      continue;
    }
    const std::string& uri = images[source].uri;
    const bool file = !uri.empty() && uri.rfind("data:", 0) != 0;
    tried += "image " + std::to_string(source) + (file ? " '" + uri + "'" : "");
  }
  return tried.empty() ? "it names no image" : tried;
}

}  // namespace

bool decodeGltfImage(tinygltf::Image* image, const int imageIndex, std::string*, std::string*, int, int,
                     const unsigned char* bytes, int size, void* user) {
  auto* decoder = static_cast<ImageDecoder*>(user);
  std::string label = "image " + std::to_string(imageIndex) + (image->name.empty() ? "" : " (" + image->name + ")");
  const std::string mime = image->mimeType.empty() ? "" : " (" + image->mimeType + ")";
  if (!bytes || size <= 0) {
    decoder->failures.push_back(label + ": no bytes" + mime);
    return true;
  }
  try {
    const uint64_t texelsLeft = decoder->limits.maxTotalTexels - std::min(decoder->decodedTexels, decoder->limits.maxTotalTexels);
    DecodedImage decoded = decodeImage(bytes, size_t(size), decoder->limits.maxDimension, texelsLeft);
    decoder->decodedTexels += uint64_t(decoded.width) * decoded.height;
    image->width = int(decoded.width);
    image->height = int(decoded.height);
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(decoded.rgba);
  } catch (const Error& e) {
    decoder->failures.push_back(label + ": " + e.what() + mime);
  }
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
    const int source = chosenSource(t, model.images);
    if (source >= 0) {
      const tinygltf::Image& img = model.images[source];
      tex.width = static_cast<uint32_t>(img.width);
      tex.height = static_cast<uint32_t>(img.height);
      tex.texels.resize(size_t(tex.width) * tex.height);
      std::memcpy(tex.texels.data(), img.image.data(), tex.texels.size() * 4);
    } else {
      warnings.push_back("texture " + std::to_string(i) + (t.name.empty() ? "" : " (" + t.name + ")") +
                         " has no image vkmc could decode (" + sourcesTried(t, model.images) + "): ignored");
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
