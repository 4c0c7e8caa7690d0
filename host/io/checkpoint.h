// A render's checkpoint file: what the render is (the caller's configuration, as JSON) and what it has done
// (RenderState: the double film, the device's unfolded float batch, the next sample index, the counters).
//
//   "VKMC-CHECKPOINT\n"  16 bytes
//   u64 header length, header (JSON text: format version, configuration, sizes, counters)
//   u64 payload length, payload (the film's arrays in the order of Film's fields, then the batch; little-endian)
//   u64 checksum of everything before it (scene/content_hash.h)
//
// Decoding checks the magic, every length against the file's size and the image's, and the checksum before it
// trusts a byte: a truncated, corrupt or foreign file is refused with one line naming the file and the problem.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "render/render_state.h"

namespace vkmc {

struct Checkpoint {
  nlohmann::json config;  // what the render is (render_job's options, outputs, scene fingerprint)
  RenderState state;
};

std::string encodeCheckpoint(const Checkpoint& checkpoint);
// Throws vkmc::Error naming `name` when the bytes are not a whole, intact checkpoint of this format version.
Checkpoint decodeCheckpoint(const std::string& bytes, const std::string& name);
// Refuses a file larger than largestCheckpointBytes() before reading it.
Checkpoint readCheckpoint(const std::string& path);
uint64_t largestCheckpointBytes();
// Whether the file at `path` starts as a vkmc checkpoint does (its magic): a path holding anything else is not
// vkmc's to overwrite or remove.
bool startsLikeCheckpoint(const std::string& path);

}  // namespace vkmc
