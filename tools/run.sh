#!/usr/bin/env bash
# The main job: install what is missing, build, render the built-in Cornell box and print the report.
# Extra arguments go to `vkmc render` (e.g. --spp 256 --png cornell.png).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
./build/vkmc render scenes/cornell_box.gltf -o cornell_box.exr --report cornell_box.json "$@"
