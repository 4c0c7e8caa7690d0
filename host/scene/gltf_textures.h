// glTF images, samplers and textures into Scene::textures, and a material's texture references (with
// KHR_texture_transform). Images are decoded by libpng and libjpeg-turbo (scene/image_decode) inside tinygltf's image callback,
// after their dimensions are checked against the loader's limits: a small file must not decode into gigabytes.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Model;
struct Image;
struct TextureInfo;
struct NormalTextureInfo;
class Value;
}  // namespace tinygltf

namespace vkmc {

struct ImageDecodeLimits {
  uint32_t maxDimension = 16384;
  uint64_t maxTotalTexels = uint64_t(1) << 28;  // over all images of a scene (4 bytes each on the device)
};

// State of tinygltf's image callback: limits, the running texel total, and the images it could not decode.
struct ImageDecoder {
  ImageDecodeLimits limits;
  uint64_t decodedTexels = 0;
  std::vector<std::string> failures;  // "image 3 (name): why"
};

// tinygltf's LoadImageDataFunction, with `user` an ImageDecoder. Never fails the load: an image it cannot
// decode is left empty and named in decoder->failures (its textures are then ignored with a warning).
bool decodeGltfImage(tinygltf::Image* image, const int imageIndex, std::string* err, std::string* warn, int reqWidth,
                     int reqHeight, const unsigned char* bytes, int size, void* user);

// Scene::textures from the model's textures (one per glTF texture, image + sampler); a texture whose image is
// missing or undecodable is kept empty (width 0) and warned about once.
std::vector<Texture> convertTextures(const tinygltf::Model& model, std::vector<std::string>& warnings);

// A material slot's reference; `what` names it in errors ("material 2 baseColorTexture").
TextureRef convertTextureRef(const tinygltf::TextureInfo& info, const std::vector<Texture>& textures, const std::string& what,
                             std::vector<std::string>& warnings);
TextureRef convertTextureRef(const tinygltf::NormalTextureInfo& info, const std::vector<Texture>& textures,
                             const std::string& what, std::vector<std::string>& warnings);

// A texture info inside a material extension (JSON: index, texCoord, scale, extensions).
TextureRef convertTextureRef(const tinygltf::Value& info, const std::vector<Texture>& textures, const std::string& what,
                             std::vector<std::string>& warnings);

}  // namespace vkmc
