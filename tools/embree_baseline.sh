#!/usr/bin/env bash
# vkmc's closest-hit traversal against Embree 3 rtcIntersect1 on the same rays, in one run (issue 6's baseline).
# Installs Debian's libembree-dev if missing (the main build never needs it), builds, runs; arguments go to the
# tool (e.g. --runs 7, --json out.json, --dump DIR, scenes).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! dpkg-query -W -f='${Status}' libembree-dev 2>/dev/null | grep -q "install ok installed"; then
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq >&2
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends libembree-dev >&2
fi
bash tools/setup.sh
cmake -S . -B build >/dev/null  # picks Embree up
cmake --build build -j"$(nproc)" --target vkmc-embree-baseline >&2
exec ./build/vkmc-embree-baseline "$@"
