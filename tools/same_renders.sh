#!/usr/bin/env bash
# Renders a dozen configurations (scenes, estimators, samplers, filters, integrators, a time-free budget) with two
# vkmc binaries and says whether each pair of EXRs is byte-identical: the check for a change that must not change
# what vkmc renders (a refactor). Exits 1 when any pair differs. EARS and splitting (light or BSDF samples above 1)
# are left out: their float atomics add in an order that differs from run to run, so two runs of one binary differ.
#   bash tools/same_renders.sh OLD_VKMC NEW_VKMC [WORK_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
[[ $# -ge 2 && -x $1 && -x $2 ]] || { echo "usage: tools/same_renders.sh OLD_VKMC NEW_VKMC [WORK_DIR]" >&2; exit 2; }
old=$(realpath "$1") new=$(realpath "$2")
work=${3:-$(mktemp -d)}
mkdir -p "$work"
helmet=../shared/scenes/DamagedHelmet/DamagedHelmet.gltf
configs=(
  "cornell scenes/cornell_box.gltf"
  "cornell_efficiency scenes/cornell_box.gltf --rr efficiency"
  "cornell_fixed scenes/cornell_box.gltf --rr fixed --rr-q 0.3 --rr-c 0.1"
  "cornell_independent_gauss scenes/cornell_box.gltf --sampler independent --filter gaussian"
  "cornell_megakernel scenes/cornell_box.gltf --integrator megakernel --max-depth 4"
  "veach_balance scenes/veach_mis.gltf --mis balance --bsdf-sampling cosine"
  "many_lights_solid_angle scenes/many_lights.gltf --light-sampling solid-angle --light-select uniform"
  "glass_bulb scenes/materials/glass_bulb.gltf --shadow-rr 0.1"
  "caustic scenes/materials/caustic.gltf --sampler zsobol --replicates 4"
  "dark_room_shadow_rr scenes/dark_room.gltf --shadow-rr 0.2 --time-budget 1000 --spp 8"
  "leaves scenes/textures/leaves.gltf --filter mitchell"
  "furnace_stiff scenes/furnace_stiff.gltf --camera-rr 0.5"
)
[[ -f $helmet ]] && configs+=("helmet $helmet --background 0.5,0.5,0.5")
differ=0
for c in "${configs[@]}"; do
  read -r name scene args <<<"$c"
  for side in old new; do
    bin=$old
    [[ $side == new ]] && bin=$new
    # shellcheck disable=SC2086
    spp=(--spp 16)
    [[ " $args " == *" --spp "* ]] && spp=()
    # --estimator defaults unless the configuration names one: a chosen estimator depends on measured time.
    est=(--estimator defaults)
    [[ " $args " == *" --estimator "* ]] && est=()
    "$bin" render "$scene" --width 64 "${spp[@]}" --seed 3 "${est[@]}" -q -o "$work/$name.$side.exr" $args
  done
  if cmp -s "$work/$name.old.exr" "$work/$name.new.exr"; then
    echo "same    $name"
  else
    echo "DIFFER  $name"
    differ=1
  fi
done
exit $differ
