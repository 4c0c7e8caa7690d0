#!/usr/bin/env bash
# Equal-time comparison of every estimator in scenes/estimators/ on the test scenes: relMSE against a
# high-sample reference (cached in build/references/), the seconds and samples reached, and efficiency
# 1/(relMSE x seconds) relative to the baseline. Writes docs/tables/estimators.md (or $OUT).
# Usage: tools/estimator_table.sh [SECONDS_PER_RENDER (default 2)] [REFERENCE_SPP (default 4096)]
set -euo pipefail
cd "$(dirname "$0")/.."
budget=${1:-2}
refspp=${2:-4096}
out=${OUT:-docs/tables/estimators.md}
vkmc=./build/vkmc
[[ -x $vkmc ]] || bash tools/setup.sh
mkdir -p build/references build/estimator-table
scenes=(cornell_box veach_mis many_lights furnace)
size="--width 128 --height 128"
{
  echo "# Estimators at equal time"
  echo
  $vkmc render scenes/furnace.gltf --width 4 --height 4 --spp 1 -q -o build/estimator-table/probe.exr --report build/estimator-table/probe.json
  echo "Produced by \`tools/estimator_table.sh $budget $refspp\` on $(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["device"])' build/estimator-table/probe.json)."
  echo "Each render gets the same wall-clock budget ($budget s, whole sample passes); relMSE is against a"
  echo "${refspp}-spp baseline render with another seed (cached in build/references/); efficiency = 1/(relMSE x"
  echo "seconds), relative to the baseline (\`--rr throughput --nee on --mis power --bsdf-sampling bsdf\`). 128x128"
  echo "pixels (Veach scene 128x85). Machines are noisy: compare within one run."
  echo
  echo "Pixel filters (\`--filter\`; not an estimator option: a filter changes what a pixel is, so it is not in these"
  echo "tables). A filter other than the default box is sampled by filter importance sampling (pbrt-v4): a sample's point"
  echo "around the pixel's centre follows |f| and its estimate is weighted f / (p ∫f), so the film stays a plain average,"
  echo "unbiased for the filtered image. The weight is nearly constant for gaussian, blackman-harris and a wider box, which"
  echo "cost only their blur; Mitchell's negative lobes make it ±(∫|f| / ∫f)² = ±1.145, so even a flat region gets a"
  echo "per-sample variance of 0.31 L² (pbrt-v4's film divides by the sum of the weights instead, which removes that at"
  echo "the price of a ratio estimator's bias). On the Cornell box (256x256, 64 spp) the image mean of the per-pixel"
  echo "variance of the mean (red) was: box 0.00119, gaussian 0.00209, blackman-harris 0.00243, box of radius 1 0.00263,"
  echo "mitchell 0.0093."
  for scene in "${scenes[@]}"; do
    ref=build/references/${scene}_${refspp}.exr
    if [[ ! -f $ref || scenes/$scene.gltf -nt $ref ]]; then
      $vkmc render scenes/$scene.gltf $size --spp "$refspp" --seed 987654 -q -o "$ref" >&2
    fi
    echo
    echo "## $scene"
    echo
    echo "| estimator | spp | seconds | rays | relMSE | efficiency vs baseline |"
    echo "|---|---|---|---|---|---|"
    base_eff=""
    for f in scenes/estimators/baseline.json $(ls scenes/estimators/*.json | grep -v baseline.json); do
      name=$(basename "$f" .json)
      rep=build/estimator-table/${scene}_${name}.json
      $vkmc render scenes/$scene.gltf $size --estimator "$f" --time-budget "$budget" --reference "$ref" -q \
        -o build/estimator-table/${scene}_${name}.exr --report "$rep" >&2
      line=$(python3 - "$rep" "$base_eff" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
eff = j["efficiency"]
base = float(sys.argv[2]) if sys.argv[2] else eff
print(f'{eff}|{j["estimator"].get("name", "")}|{j["spp_reached"]}|{j["seconds"]:.2f}|{j["rays"]:,}|{j["relmse"]:.3g}|{eff / base:.2f}')
PY
)
      eff=${line%%|*}
      [[ -z $base_eff ]] && base_eff=$eff
      rest=${line#*|}
      echo "| ${name} | ${rest#*|} |" | sed 's/|/ | /g; s/  */ /g; s/^ //; s/ $//'
    done
  done
} > "$out.tmp"
mv "$out.tmp" "$out"
echo "wrote $out" >&2
