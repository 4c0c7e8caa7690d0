#!/usr/bin/env python3
"""Writes tests/fuzz/regressions/: self-contained crafted glTF files that crashed, over-read or overflowed the
stack before vkmc's input checks (issue: the scene path must be trustworthy). tools/fuzz.sh replays each through
the ASan/UBSan harness before fuzzing; the loader tests check the same cases' messages."""
import base64, json, os, struct

here = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(here, "..", "..", "tests", "fuzz", "regressions")
os.makedirs(out, exist_ok=True)

positions = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]
indices = [0, 1, 2, 0, 2, 3]
binary = struct.pack("<12f", *positions) + struct.pack("<6I", *indices)


def quad(position_count=4, accessor_offset=0, view_offset=0, extras=None, uri=True, index_values=None):
    data = binary if index_values is None else struct.pack("<12f", *positions) + struct.pack("<6I", *index_values)
    doc = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [{"bufferView": 0, "byteOffset": accessor_offset, "componentType": 5126, "type": "VEC3", "count": position_count},
                      {"bufferView": 1, "componentType": 5125, "type": "SCALAR", "count": 6}],
        "bufferViews": [{"buffer": 0, "byteOffset": view_offset, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
        "buffers": [{"byteLength": len(data)}],
    }
    if uri:
        doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    text = json.dumps(doc, separators=(",", ":"))
    if extras is not None:
        text = text[:-1] + ',"extras":' + extras + "}"
    return text, data


def write(name, content):
    with open(os.path.join(out, name), "wb") as f:
        f.write(content if isinstance(content, bytes) else content.encode())


# count 2^62 + 1 wraps the size_t bounds check; index 1e6 then reads 12 MB past the buffer.
write("accessor_count_wraps.gltf", quad(position_count=2**62 + 1, index_values=[0, 1, 2, 0, 2, 1000000])[0])
# Offsets near 2^64 wrap the sums and point before the buffer.
write("accessor_offset_wraps.gltf", quad(accessor_offset=2**64 - 16)[0])
write("view_offset_wraps.gltf", quad(view_offset=2**64 - 16)[0])
# 20 000 nested arrays: tinygltf's JSON-to-Value conversion recursed until the stack overflowed.
write("deep_extras.gltf", quad(extras="[" * 20000 + "]" * 20000)[0])
# A GLB whose BIN chunk claims 8 bytes more than the file holds (tinygltf 2.7.0 forgets the chunk header).
text, data = quad(uri=False)
text = text.encode() + b" " * (-len(text) % 4)
data += b"\0" * (-len(data) % 4)
glb = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(text) + 8 + len(data))
glb += struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data) + 8, 0x004E4942) + data
write("glb_bin_chunk_too_long.glb", glb)
# Coordinates of ±3e38 with a normal texture and no TANGENT: MikkTSpace's FindGridCell converted a NaN cell
# index ((fVal - fMin) / (fMax - fMin) = inf / inf) to int, undefined behaviour (found by the fuzzer, 2026-11-29).
huge = [-3e38, 0, 0, 3e38, 0, 0, 3e38, 1, 0, -3e38, 1, 0]
uvs = [0, 0, 1, 0, 1, 1, 0, 1]
data = struct.pack("<12f", *huge) + struct.pack("<6I", *indices) + struct.pack("<8f", *uvs)
doc = {
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "indices": 1, "material": 0}]}],
    "materials": [{"normalTexture": {"index": 0}}],
    "textures": [{"source": 0}],
    "images": [{"uri": "data:image/png;base64," + base64.b64encode(bytes.fromhex(
        "89504e470d0a1a0a0000000d4948445200000001000000010802000000907753de0000000c4944415478da63f8ffff3f0005fe02fe"
        "a7d6a8ad0000000049454e44ae426082")).decode()}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 4},
                  {"bufferView": 1, "componentType": 5125, "type": "SCALAR", "count": 6},
                  {"bufferView": 2, "componentType": 5126, "type": "VEC2", "count": 4}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 24},
                    {"buffer": 0, "byteOffset": 72, "byteLength": 32}],
    "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
}
write("tangents_huge_coordinates.gltf", json.dumps(doc, separators=(",", ":")))
# An image whose bufferView starts 8 GiB past its 72-byte buffer: tinygltf handed the image decoder that pointer
# (SIGSEGV) before vkmc's guard had seen the views (found by a hostile-input probe, 2026-12-06).
text, data = quad()
doc = json.loads(text)
doc["bufferViews"].append({"buffer": 0, "byteOffset": 2**33, "byteLength": 16})
doc["images"] = [{"bufferView": 2, "mimeType": "image/png"}]
doc["textures"] = [{"source": 0}]
write("image_view_past_buffer.gltf", json.dumps(doc, separators=(",", ":")))
