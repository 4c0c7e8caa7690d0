#!/usr/bin/env bash
# Issue 17's floor, scene by scene: `--rr ears` (its guard, the default) against throughput roulette by concurrent
# pairs (tools/paired_efficiency.py) on every scene of scenes/ whose image has variance to compare, and the method's
# control (throughput roulette against itself, one seed a pair as in the comparison) beside it. Prints one row a
# scene; docs/journal/ears.md, "Concurrent pairs".
#   bash tools/ears_floor.sh [--seconds S] [--pairs N] [--seed K] [--out DIR] [--control off] [scene ...]
# Default: 16 s, 4 pairs, seeds from 1 (pair k: K + 2k), every scene below; references are rendered once (8192 spp,
# cached) or analytic.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=16 pairs=4 seed=1 out=/tmp/vkmc-ears-floor control=on
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --pairs) pairs="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --control) control="$2"; shift 2 ;;
    -h|--help) sed -n 2,8p "$0"; exit 0 ;;
    -*) echo "ears_floor: unknown option $1" >&2; exit 1 ;;
    *) break ;;
  esac
done
scenes=("$@")
# Left out: the glass and mirror furnaces and the tiny light, whose images have no variance to compare.
[[ ${#scenes[@]} -gt 0 ]] || scenes=(cornell_box two_rooms glossy_room dark_room basement soft_shadows desk_lamp
  furnace furnace_stiff stiff/furnace_albedo_0999 many_lights veach_mis materials/caustic materials/glass_bulb
  textures/leaves)
# The furnaces' analytic radiance, Le / (1 - albedo).
declare -A constant=([furnace]=2 [furnace_stiff]=100 [stiff/furnace_albedo_0999]=1000)
# A result file's row: geometric mean (95% interval), median.
summary() {
  python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); i=j["interval95"] or [float("nan")] * 2
print("%.3f (%.3f-%.3f), %.3f" % (j["geometric_mean"], *i, j["median"]))' "$1"
}
mkdir -p "$out"
printf '%-28s %-34s %-34s\n' scene "ears / throughput (95%, median)" "control (95%, median)"
for s in "${scenes[@]}"; do
  ref=()
  [[ -n "${constant[$s]:-}" ]] && ref=(--reference-constant "${constant[$s]}")
  name=${s//\//_}
  python3 tools/paired_efficiency.py "scenes/$s.gltf" --seconds "$seconds" --pairs "$pairs" --seed "$seed" \
    "${ref[@]}" --json "$out/$name.ears.json" >"$out/$name.ears.log"
  row=$(summary "$out/$name.ears.json")
  crow=-
  if [[ $control == on ]]; then
    python3 tools/paired_efficiency.py "scenes/$s.gltf" --seconds "$seconds" --pairs "$pairs" --seed "$seed" \
      "${ref[@]}" --b scenes/estimators/baseline.json --json "$out/$name.control.json" >"$out/$name.control.log"
    crow=$(summary "$out/$name.control.json")
  fi
  printf '%-28s %-34s %-34s\n' "$s" "$row" "$crow"
done
