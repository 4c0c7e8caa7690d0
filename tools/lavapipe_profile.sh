#!/usr/bin/env bash
# Where lavapipe spends a render's time, kernel code by kernel code: samples a running `vkmc render` with perf,
# copies its JIT code regions out of /proc/PID/mem, disassembles them and prints, per region (one compiled kernel
# each, largest share first), its share of the samples and the share spent in per-lane loops (llvmpipe's
# storage-buffer loads and stores: one loop over the 8 lanes per access). docs/journal/performance.md, "Reading the
# kernels' machine code". Needs perf and objdump (linux-perf, binutils); run as root (or with ptrace rights).
#   bash tools/lavapipe_profile.sh [--warm-up S] [--seconds S] [--out DIR] [--] [render args...]
# Default render: the Cornell box, 256x256, 4096 spp (long enough to sample; it is stopped when done).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
warmup=5 seconds=6 out=/tmp/vkmc-lavapipe-profile
while [[ $# -gt 0 ]]; do
  case "$1" in
    --warm-up) warmup="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n 2,8p "$0"; exit 0 ;;
    *) break ;;
  esac
done
args=("$@")
[[ ${#args[@]} -gt 0 ]] || args=("$root/scenes/cornell_box.gltf" --spp 4096)
for tool in perf objdump python3; do
  command -v "$tool" >/dev/null || { echo "lavapipe_profile: $tool is missing (apt-get install linux-perf binutils)" >&2; exit 1; }
done
vkmc="${VKMC:-$root/build/vkmc}"
[[ -x "$vkmc" ]] || { echo "lavapipe_profile: no $vkmc (build first, or set VKMC)" >&2; exit 1; }
mkdir -p "$out"
rm -f "$out"/region_* "$out"/perf.data "$out"/regions.txt
"$vkmc" render "${args[@]}" -o "$out/render.exr" -q >/dev/null 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
sleep "$warmup"
kill -0 "$pid" 2>/dev/null || { echo "lavapipe_profile: the render ended within the warm-up; give it more samples" >&2; exit 1; }
perf record -F 2000 -p "$pid" -o "$out/perf.data" -- sleep "$seconds" >/dev/null 2>&1
python3 "$here/lavapipe_profile/dump_jit.py" "$pid" "$out"
kill "$pid" 2>/dev/null || true
perf script -i "$out/perf.data" -F ip 2>/dev/null > "$out/samples.txt"
python3 "$here/lavapipe_profile/report.py" "$out"
