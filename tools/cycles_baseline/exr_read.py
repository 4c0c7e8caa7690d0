"""Reads single-part scanline OpenEXR files of 32-bit float channels, uncompressed or ZIP (what vkmc and the
Cycles baseline write), in plain Python: no numpy or OpenEXR bindings needed. read_exr(path) -> (width, height,
{channel: array('f') of width*height values, row-major, top row first})."""
import array
import struct
import zlib

_COMPRESSION = {0: ("none", 1), 2: ("zips", 1), 3: ("zip", 16)}


def _header(data):
    if struct.unpack_from("<I", data, 0)[0] != 20000630:
        raise ValueError("not an OpenEXR file")
    pos, attrs = 8, {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        end2 = data.index(b"\0", end + 1)
        kind = data[end + 1:end2].decode()
        size = struct.unpack_from("<i", data, end2 + 1)[0]
        value = data[end2 + 5:end2 + 5 + size]
        attrs[name] = (kind, value)
        pos = end2 + 5 + size
    return attrs, pos + 1


def _channels(value):
    names, pos = [], 0
    while value[pos] != 0:
        end = value.index(b"\0", pos)
        pixel_type = struct.unpack_from("<i", value, end + 1)[0]
        if pixel_type != 2:
            raise ValueError("only 32-bit float channels are supported")
        names.append(value[pos:end].decode())
        pos = end + 1 + 16
    return names


def _unzip(raw, expected):
    t = bytearray(zlib.decompress(raw))
    for i in range(1, len(t)):  # undo the byte predictor
        t[i] = (t[i - 1] + t[i] - 128) & 0xFF
    half = (len(t) + 1) // 2
    out = bytearray(len(t))
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    if len(out) != expected:
        raise ValueError("bad ZIP block")
    return bytes(out)


def read_exr(path):
    with open(path, "rb") as f:
        data = f.read()
    attrs, pos = _header(data)
    xmin, ymin, xmax, ymax = struct.unpack("<4i", attrs["dataWindow"][1])
    width, height = xmax - xmin + 1, ymax - ymin + 1
    names = _channels(attrs["channels"][1])
    compression = attrs["compression"][1][0]
    if compression not in _COMPRESSION:
        raise ValueError(f"unsupported EXR compression {compression}")
    lines_per_block = _COMPRESSION[compression][1]
    blocks = (height + lines_per_block - 1) // lines_per_block
    offsets = struct.unpack_from(f"<{blocks}Q", data, pos)
    out = {n: array.array("f", bytes(4 * width * height)) for n in names}
    for off in offsets:
        y, size = struct.unpack_from("<ii", data, off)
        raw = data[off + 8:off + 8 + size]
        lines = min(lines_per_block, ymax - y + 1)
        expected = lines * len(names) * width * 4
        block = raw if size == expected else _unzip(raw, expected)
        values = array.array("f", block)
        for line in range(lines):
            row = y - ymin + line
            for c, n in enumerate(names):
                start = (line * len(names) + c) * width
                out[n][row * width:(row + 1) * width] = values[start:start + width]
    return width, height, out
