#!/usr/bin/env bash
# What checkpoints cost: the same render without and with --checkpoint (every EVERY seconds), interleaved round by
# round; medians of the render seconds, the seconds spent writing checkpoints, their size, and the share the
# default interval (120 s, spaced to at most 2%) would cost.
#   bash tools/checkpoint_overhead.sh [ROUNDS] [EVERY] [vkmc render options...]
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-3}
every=${2:-2}
shift $(( $# > 2 ? 2 : $# ))
args=("$@")
[ ${#args[@]} -eq 0 ] && args=(scenes/cornell_box.gltf --spp 256)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for ((r = 0; r < rounds; ++r)); do
  # The fixed defaults on both sides: a checkpointed render does not choose its estimator, a plain one would.
  build/vkmc render "${args[@]}" --estimator defaults -q -o "$out/plain.exr" --report "$out/plain-$r.json"
  build/vkmc render "${args[@]}" -q -o "$out/ckpt.exr" --report "$out/ckpt-$r.json" --checkpoint "$out/c.ckpt" \
    --checkpoint-every "$every"
done
python3 - "$out" "$rounds" "$every" <<'PY'
import json, statistics, sys
d, rounds, every = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
plain = [json.load(open(f"{d}/plain-{r}.json")) for r in range(rounds)]
ckpt = [json.load(open(f"{d}/ckpt-{r}.json")) for r in range(rounds)]
p = statistics.median(j["seconds"] for j in plain)
c = statistics.median(j["seconds"] for j in ckpt)
writes = [j["checkpoint_seconds"] / j["checkpoints_written"] for j in ckpt if j["checkpoints_written"]]
pixels = plain[0]["width"] * plain[0]["height"]
print(f"render without checkpoints: median {p:.2f} s [{min(j['seconds'] for j in plain):.2f}-{max(j['seconds'] for j in plain):.2f}]")
print(f"render with one every {every:g} s: median {c:.2f} s [{min(j['seconds'] for j in ckpt):.2f}-{max(j['seconds'] for j in ckpt):.2f}], "
      f"{statistics.median(j['checkpoints_written'] for j in ckpt):.0f} checkpoints")
if writes:
    w = statistics.median(writes)
    print(f"one checkpoint ({pixels} pixels, {pixels * 200 / 1e6:.1f} MB, {pixels * 312 / 1e6:.1f} with an unfolded batch): median {w * 1000:.1f} ms to encode and write")
    print(f"share of render time: {100 * w / every:.2f}% at every {every:g} s; {100 * w / 120:.3f}% at the default 120 s")
    print(f"ratio of median render times with/without: {c / p:.3f} (machine noise included)")
PY
