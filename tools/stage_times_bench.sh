#!/usr/bin/env bash
# What stage timestamps cost: each render with --stage-times on, then off, alternated for ROUNDS rounds (default
# 5); prints each round's wall seconds, then per render the medians and the median of the per-round ratios off/on.
# Run from the repository root after tools/setup.sh; docs/journal/performance.md, "Stage timestamps".
set -euo pipefail
rounds=${1:-5}
helmet=../shared/scenes/DamagedHelmet/DamagedHelmet.gltf
renders=("scenes/cornell_box.gltf --spp 64"
         "scenes/dark_room.gltf --width 96 --height 96 --spp 112"
         "scenes/dark_room.gltf --width 96 --height 96 --spp 128 --rr ears --ears-fallback never"
         "scenes/cornell_box.gltf --width 40 --height 30 --spp 4")
[ -f "$helmet" ] && renders+=("$helmet --spp 32")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for ((i = 1; i <= rounds; ++i)); do
  for mode in on off; do
    for k in "${!renders[@]}"; do
      # shellcheck disable=SC2086
      ./build/vkmc render ${renders[$k]} --seed 1 --stage-times "$mode" -o "$tmp/out.exr" --report "$tmp/r.json" -q
      python3 -c "import json,sys; print(sys.argv[1], sys.argv[2], sys.argv[3], json.load(open(sys.argv[4]))['seconds'])" \
        "$k" "$mode" "$i" "$tmp/r.json" >>"$tmp/times"
    done
  done
done
python3 - "$tmp/times" "${renders[@]}" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
names = sys.argv[2:]
print(f"{'render':<90} {'on s':>7} {'off s':>7} {'off/on':>7}")
for k, name in enumerate(names):
    t = {(m, int(i)): float(s) for kk, m, i, s in rows if int(kk) == k}
    rounds = sorted({i for _, i in t})
    on = [t[('on', i)] for i in rounds]; off = [t[('off', i)] for i in rounds]
    ratio = statistics.median(b / a for a, b in zip(on, off))
    print(f"{name:<90} {statistics.median(on):7.3f} {statistics.median(off):7.3f} {ratio:7.2f}")
PY
