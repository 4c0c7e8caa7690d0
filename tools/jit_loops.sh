#!/usr/bin/env bash
# The loops of llvmpipe's compiled kernels, counted instead of timed: runs a command (a vkmc render, a baseline
# tool) for a few seconds, copies its JIT code out of /proc (lavapipe_profile/dump_jit.py) and prints the largest
# loops with their instructions, spills and selects (lavapipe_profile/loops.py). COMMAND must be the process that
# runs lavapipe itself (a binary, or a script that execs it), not a wrapper that starts it as a child. Needs
# objdump; run as root (or with ptrace rights). docs/journal/performance.md, "Traversal against Embree", uses it.
#   bash tools/jit_loops.sh [--wait S] [--out DIR] -- COMMAND...
# e.g. bash tools/jit_loops.sh -- ./build/vkmc render scenes/cornell_box.gltf --spp 8192 -o /tmp/r.exr -q
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
wait=8 out=/tmp/vkmc-jit-loops
while [[ $# -gt 0 ]]; do
  case "$1" in
    --wait) wait="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n 2,8p "$0"; exit 0 ;;
    -*) echo "jit_loops: unknown option $1 (the command goes after --)" >&2; exit 1 ;;
    *) break ;;
  esac
done
[[ $# -gt 0 ]] || { echo "jit_loops: give the command after --" >&2; exit 1; }
command -v objdump >/dev/null || { echo "jit_loops: objdump is missing (apt-get install binutils)" >&2; exit 1; }
mkdir -p "$out"
rm -f "$out"/region_* "$out"/regions.txt
"$@" >"$out/command.log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
sleep "$wait"
if ! kill -0 "$pid" 2>/dev/null; then
  echo "jit_loops: the command ended within ${wait} s (give it more work); its last output:" >&2
  tail -n 5 "$out/command.log" >&2
  exit 1
fi
python3 "$here/lavapipe_profile/dump_jit.py" "$pid" "$out"
[[ -s "$out/regions.txt" ]] || { echo "jit_loops: no JIT code in process $pid (a wrapper? run the binary itself)" >&2; exit 1; }
python3 "$here/lavapipe_profile/loops.py" "$out"
