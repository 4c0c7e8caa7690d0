#!/usr/bin/env bash
# vkmc's closest-hit traversal against tinybvh's GPU traversal kernels (its GLSL Aila-Laine walk, its CWBVH walk
# ported from OpenCL) on the same device and rays, in one run (issue 19's second peer). tinybvh is vendored
# (third_party/tinybvh), so nothing is installed; builds the tool (outside the main build) and runs it. Arguments
# go to the tool (e.g. --runs 7, --json out.json, --walk-stats, --hq, --dump DIR, --rays FILE, scenes).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake -S . -B build >/dev/null
cmake --build build -j"$(nproc)" --target vkmc-tinybvh-baseline >&2
exec ./build/vkmc-tinybvh-baseline "$@"
