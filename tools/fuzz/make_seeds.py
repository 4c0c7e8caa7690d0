#!/usr/bin/env python3
"""Writes seed inputs for the reader harnesses into OUT/<harness>/: Radiance files (run-length encoded and flat),
checkpoint-shaped bytes (magic, lengths, a header of the right keys; the harness reseals the checksum), PNG and
JPEG images. Usage: make_seeds.py OUT"""
import json, os, struct, sys, zlib

out = sys.argv[1]


def write(harness, name, data):
    os.makedirs(os.path.join(out, harness), exist_ok=True)
    with open(os.path.join(out, harness, name), "wb") as f:
        f.write(data)


def radiance(width, height, rle):
    s = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width)
    for _ in range(height):
        if not rle:
            s += bytes([128, 64, 32, 129]) * width
            continue
        s += bytes([2, 2, width >> 8, width & 0xFF])
        for value in (128, 64, 32, 129):
            x = 0
            while x < width:
                run = min(127, width - x)
                s += bytes([128 + run, value])
                x += run
    return s


write("radiance_fuzzer", "rle.hdr", radiance(40, 3, True))
write("radiance_fuzzer", "flat.hdr", radiance(5, 2, False))
write("radiance_fuzzer", "wide.hdr", radiance(300, 1, True))

stats = {k: 0 for k in ("seconds", "gpu_seconds", "camera_rays", "extension_rays", "shadow_rays", "primary_rays",
                        "primary_seconds", "incoherent_seconds", "passes", "max_bounces", "samples_per_pixel",
                        "nonfinite_emission", "nonfinite_light_samples", "nonfinite_throughput", "traversals_cut",
                        "deep_walks", "deep_walks_traced", "splits_refused")}
stats.update({"stage_seconds": {}, "stages_untimed": False, "paths_by_bounce": [], "shadow_rays_by_bounce": []})
header = json.dumps({"format": "vkmc checkpoint", "version": 2, "config": {}, "width": 1, "height": 1,
                     "replicate_variance": True, "replicates": 2, "next_sample": 1, "batch_samples": 0,
                     "stats": stats}).encode()
payload = bytes(1024)
body = b"VKMC-CHECKPOINT\n" + struct.pack("<Q", len(header)) + header + struct.pack("<Q", len(payload)) + payload
write("checkpoint_fuzzer", "shaped.ckpt", body + bytes(8))


def png(width, height):
    rows = b"".join(b"\0" + b"".join(bytes([(x * 40) % 256, (y * 60) % 256, 128, 255]) for x in range(width))
                    for y in range(height))
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


write("image_fuzzer", "rgba.png", png(4, 3))
