#!/usr/bin/env bash
# Installs the Debian 12 packages vkmc needs (only those missing) and builds it (Release) into build/.
# Used by tools/run.sh and tools/test.sh; safe to run again. With --test-tools (tools/test.sh) it also installs what
# the whole suite runs: Open MPI (the `dist` tests, `mpirun`) and clang with its libFuzzer runtime (the `fuzz` test).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make pkg-config libvulkan-dev mesa-vulkan-drivers glslang-tools spirv-tools libglm-dev libtinygltf-dev
          libopenexr-dev openexr libgtest-dev libcli11-dev nlohmann-json3-dev libpng-dev libstb-dev libdraco-dev
          libmeshoptimizer-dev libjpeg-dev libwebp-dev libzstd-dev libxml2-utils python3)
[[ ${1:-} == --test-tools ]] && packages+=(openmpi-bin libopenmpi-dev clang clang-format libclang-rt-dev)
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

# MPI's cached detection is dropped so that a build configured before Open MPI was installed finds it now.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -U 'MPI_*' >/dev/null
cmake --build build -j"$(nproc)" >&2
