#!/usr/bin/env bash
# Installs the Debian 12 packages vkmc needs (only those missing) and builds it (Release) into build/.
# Used by tools/run.sh and tools/test.sh; safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make pkg-config libvulkan-dev mesa-vulkan-drivers glslang-tools spirv-tools libglm-dev libtinygltf-dev
          libopenexr-dev openexr libgtest-dev libcli11-dev nlohmann-json3-dev libpng-dev libstb-dev libdraco-dev
          libmeshoptimizer-dev libxml2-utils python3)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "vkmc setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq >&2
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" >&2
