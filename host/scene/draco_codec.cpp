// libdraco behind plain types (see draco_codec.h for why this is a library of its own).
#include "scene/draco_codec.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>

namespace vkmc {

DracoDecoded decodeDracoMesh(const unsigned char* data, size_t size, const std::vector<DracoAttributeRequest>& requests,
                             uint64_t maxTriangles, uint64_t maxBytes) {
  DracoDecoded out;
  draco::DecoderBuffer input;
  input.Init(reinterpret_cast<const char*>(data), size);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&input);
  if (!decoded.ok()) return {"Draco decoding failed: " + decoded.status().error_msg_string()};
  std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  if (!mesh) return {"Draco decoding gave no mesh"};
  if (mesh->num_faces() > maxTriangles)
    return {std::to_string(mesh->num_faces()) + " triangles, more than the loader's limit of " + std::to_string(maxTriangles)};
  uint64_t bytes = uint64_t(mesh->num_faces()) * 12;
  for (const DracoAttributeRequest& r : requests) bytes += uint64_t(mesh->num_points()) * 4 * uint64_t(r.components);
  if (bytes > maxBytes) return {"decoded data of " + std::to_string(bytes) + " bytes passes the loader's limit"};
  out.points = mesh->num_points();
  out.indices.resize(size_t(mesh->num_faces()) * 3);
  for (uint32_t f = 0; f < mesh->num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      uint32_t v = mesh->face(draco::FaceIndex(f))[k].value();
      if (v >= out.points) return {"Draco face " + std::to_string(f) + " refers to point " + std::to_string(v)};
      out.indices[3 * size_t(f) + k] = v;
    }
  for (const DracoAttributeRequest& r : requests) {
    const draco::PointAttribute* att = mesh->GetAttributeByUniqueId(r.uniqueId);
    if (!att) return {"no Draco attribute with id " + std::to_string(r.uniqueId)};
    if (r.components < 1 || r.components > 4) return {"invalid component count"};
    std::vector<float>& values = out.attributes.emplace_back(size_t(out.points) * r.components);
    float point[4];
    for (uint32_t p = 0; p < out.points; ++p) {
      std::fill(point, point + 4, 0.0f);
      if (!att->ConvertValue<float>(att->mapped_index(draco::PointIndex(p)), int8_t(r.components), point))
        return {"Draco attribute " + std::to_string(r.uniqueId) + " cannot be converted to floats"};
      std::copy(point, point + r.components, values.begin() + size_t(p) * r.components);
    }
  }
  return out;
}

DracoEncoded encodeDracoMesh(const std::vector<float>& positions, const std::vector<float>& uvs,
                             const std::vector<uint32_t>& indices, int bits, bool sequential) {
  draco::Mesh mesh;
  uint32_t n = static_cast<uint32_t>(positions.size() / 3);
  mesh.set_num_points(n);
  auto add = [&](draco::GeometryAttribute::Type type, int components, const std::vector<float>& values) {
    draco::GeometryAttribute ga;
    ga.Init(type, nullptr, int8_t(components), draco::DT_FLOAT32, false, 4 * components, 0);
    int att = mesh.AddAttribute(ga, true, n);
    for (uint32_t v = 0; v < n; ++v)
      mesh.attribute(att)->SetAttributeValue(draco::AttributeValueIndex(v), &values[size_t(components) * v]);
    return mesh.attribute(att)->unique_id();
  };
  DracoEncoded out;
  out.positionId = add(draco::GeometryAttribute::POSITION, 3, positions);
  if (uvs.size() == 2 * size_t(n)) out.uvId = add(draco::GeometryAttribute::TEX_COORD, 2, uvs);
  for (size_t t = 0; t + 2 < indices.size(); t += 3)
    mesh.AddFace({draco::PointIndex(indices[t]), draco::PointIndex(indices[t + 1]), draco::PointIndex(indices[t + 2])});
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, bits);
  encoder.SetEncodingMethod(sequential ? draco::MESH_SEQUENTIAL_ENCODING : draco::MESH_EDGEBREAKER_ENCODING);
  draco::EncoderBuffer buffer;
  if (!encoder.EncodeMeshToBuffer(mesh, &buffer).ok()) return out;
  out.bytes.assign(buffer.data(), buffer.data() + buffer.size());
  return out;
}

}  // namespace vkmc
