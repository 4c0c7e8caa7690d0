#!/usr/bin/env bash
# vkmc on a lent GPU machine (issue 19): one short, prepared run of `vkmc info`, `vkmc bench-kernels`,
# `vkmc bench-textures`, EARS against throughput roulette and the per-depth pilot at equal time (issue 17: whether
# EARS's vertex, twice throughput roulette's on lavapipe, is cheap on a GPU) and a render of every shared scene, with
# the same commands runnable here on lavapipe for the side-by-side figures (GPU_CHECK_QUICK=1: about a minute).
#
#   bash tools/gpu_check.sh bundle     # here: .gpu/ = vkmc + the shared libraries it needs + ../shared/scenes,
#                                      #       .gl/ = the Vulkan loader's .deb (the device machine has no loader)
#   bash tools/gpu_check.sh run OUTDIR # there (or here, for lavapipe): every check, logs and reports in OUTDIR
#
# On the device tool: run(command="bash tools/gpu_check.sh run $OUT", carry=[".gpu", ".gl"]). Both folders are
# ignored by git. The bundle carries every library of `ldd build/vkmc` that is not glibc's or the C++ runtime's.
set -uo pipefail
cd "$(dirname "$0")/.."

bundle() {
  set -e
  rm -rf .gpu && mkdir -p .gpu/lib .gpu/scenes .gl
  cp build/vkmc .gpu/
  ldd build/vkmc | awk '/=> \// {print $3}' | grep -vE '/(libc|libm|libgcc_s|libstdc\+\+|ld-linux|libvulkan)\.so' |
    while read -r lib; do cp -L "$lib" .gpu/lib/; done
  cp -r ../shared/scenes/. .gpu/scenes/
  if ! ls .gl/libglvnd0_*.deb >/dev/null 2>&1; then
    mkdir -p /tmp/amd64/partial
    local o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64'
    apt-get $o update -qq && (cd .gl && apt-get $o download libvulkan1 libglvnd0 libglx0 libgl1 libegl1 libopengl0 libgles2)
  fi
  du -sh .gpu .gl
}

run_checks() {
  local out=$1
  mkdir -p "$out/reports"
  local vkmc=./build/vkmc scenes=../shared/scenes
  if [[ -x .gpu/vkmc ]]; then
    vkmc=./.gpu/vkmc scenes=.gpu/scenes
    export LD_LIBRARY_PATH=$PWD/.gpu/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  fi
  if ls .gl/*.deb >/dev/null 2>&1; then
    for f in .gl/*.deb; do dpkg -x "$f" /; done
    ldconfig
  fi
  local icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
  [[ -f $icd ]] && export VK_DRIVER_FILES=$icd
  command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv
  local models=("$scenes/DamagedHelmet/DamagedHelmet.gltf" "$scenes/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.gltf")
  local t=timeout runs=5 big=1024 bigspp=16
  # GPU_CHECK_QUICK=1: a smoke test of this script (one run, small sizes), e.g. here on lavapipe before a lease.
  [[ ${GPU_CHECK_QUICK:-0} == 1 ]] && runs=1 big=256 bigspp=1 && models=("${models[0]}")
  echo "== info"
  $t 60 $vkmc info scenes/cornell_box.gltf
  echo "== bench-kernels 256x256, 4 spp: wavefront and megakernel side by side"
  $t 240 $vkmc bench-kernels --runs $runs --integrator wavefront megakernel --json "$out/reports/bench_256.json" scenes/cornell_box.gltf "${models[@]}"
  echo "== bench-kernels 1024x1024, 16 spp"
  $t 240 $vkmc bench-kernels --runs $runs --spp $bigspp --width $big --height $big --integrator wavefront megakernel \
    --json "$out/reports/bench_1024.json" scenes/cornell_box.gltf "${models[@]}"
  echo "== bench-kernels: workgroup and wavefront sizes (device_tuning.h's rules, unmeasured on a GPU), Cornell box ${big}x${big}"
  local wg wf
  for wg in 32 64 128 256; do
    $t 60 $vkmc bench-kernels --runs $runs --spp $bigspp --width $big --height $big --integrator wavefront megakernel \
      --workgroup $wg --json "$out/reports/bench_wg$wg.json" scenes/cornell_box.gltf | grep -E "^device|cornell"
  done
  for wf in 262144 1048576 4194304; do
    $t 60 $vkmc bench-kernels --runs $runs --spp $bigspp --width $big --height $big --integrator wavefront megakernel \
      --wavefront $wf --json "$out/reports/bench_wf$wf.json" scenes/cornell_box.gltf | grep -E "^device|cornell"
  done
  echo "== bench-kernels: specialized against general pipelines"
  $t 120 $vkmc bench-kernels --runs $runs --specialization --json "$out/reports/bench_spec.json" scenes/cornell_box.gltf "${models[0]}"
  echo "== bench-textures: sampled texture pages against a texel buffer"
  $t 120 $vkmc bench-textures --rounds $runs "${models[0]}"
  echo "== EARS against throughput roulette and the per-depth pilot at equal time (issue 17: is EARS's vertex cheap here?)"
  # The wavefront (the megakernel refuses EARS); the report's honest efficiency 1/(mean_relvariance x seconds).
  local budget=2 rr s
  [[ ${GPU_CHECK_QUICK:-0} == 1 ]] && budget=0.5
  for s in two_rooms glossy_room cornell_box; do
    for rr in throughput efficiency "ears --ears-fallback never" ears; do
      # shellcheck disable=SC2086  # $rr holds the option and its fallback
      $t 120 $vkmc render scenes/$s.gltf --integrator wavefront --time-budget $budget --spp 1000000 --rr $rr -q \
        -o "$out/ears.exr" --report "$out/ears.json" || echo "$s --rr $rr failed (exit $?)"
      [[ -f $out/ears.json ]] && python3 -c "import json,sys; r=json.load(open(sys.argv[1])); \
print('%-12s %-28s spp %6d  s %6.2f  mean_relvariance %.3g  efficiency %.4g' % (sys.argv[2], sys.argv[3], r['spp'], \
r['seconds'], r['mean_relvariance'], r['estimated_efficiency']))" "$out/ears.json" "$s" "$rr" 2>/dev/null
      rm -f "$out/ears.exr" "$out/ears.json"
    done
  done
  echo "== renders: every shared scene and the built-in ones, 64 spp at 256 wide"
  local name
  for s in scenes/cornell_box.gltf scenes/veach_mis.gltf scenes/many_lights.gltf scenes/textures/leaves.gltf $(find "$scenes" -name '*.gltf' -o -name '*.glb' | sort); do
    name=$(basename "${s%.*}")
    echo "-- $name"
    $t 120 $vkmc render "$s" --spp 64 -q -o "$out/reports/$name.exr" --report "$out/reports/$name.json" ||
      echo "render of $name failed (exit $?)"
    [[ -f $out/reports/$name.json ]] && python3 -c "import json,sys; r=json.load(open(sys.argv[1])); \
print({k: r.get(k) for k in ('device','integrator','device_tuning','seconds','gpu_seconds','rays','mrays_per_second','mean','nonfinite_samples')})" \
      "$out/reports/$name.json" 2>/dev/null
  done
  tar -C "$out" -czf "$out/reports.tar.gz" reports && rm -rf "$out/reports"
}

case "${1:-}" in
  bundle) bundle ;;
  run) run_checks "${2:?usage: gpu_check.sh run OUTDIR}" ;;
  *) echo "usage: bash tools/gpu_check.sh bundle | run OUTDIR" >&2; exit 2 ;;
esac
