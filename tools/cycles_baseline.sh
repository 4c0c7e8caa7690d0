#!/usr/bin/env bash
# vkmc against Blender's Cycles (CPU, headless) on one glTF scene, at equal spp and at equal time, both measured
# against a cached high-spp vkmc reference (issue 14; docs/journal/cycles.md). Usage:
#   bash tools/cycles_baseline.sh SCENE [SECONDS] [--width W --height H --spp 1 4 16 64 --repeats R --ref-spp N ...]
# Installs Debian's blender and python3-numpy if missing (the main build never needs them), builds vkmc, then runs
# tools/cycles_baseline/baseline.py (--help lists every option). Renders and the reference go to build/cycles_baseline/.
set -euo pipefail
cd "$(dirname "$0")/.."
missing=()
for p in blender python3-numpy openexr; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq >&2
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
if [[ -x build/vkmc ]]; then
  cmake --build build -j"$(nproc)" --target vkmc >&2  # up to date: a no-op
else
  bash tools/setup.sh
fi
exec python3 tools/cycles_baseline/baseline.py "$@"
