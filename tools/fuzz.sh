#!/usr/bin/env bash
# Fuzzes the glTF loader and the BVH build with libFuzzer (clang, ASan, UBSan) for SECONDS (default 60):
#   bash tools/fuzz.sh [SECONDS] [extra libFuzzer flags]
#   bash tools/fuzz.sh build      (only builds the fuzzer: tools/test.sh does, so that the suite's run is a run)
# First it replays tests/fuzz/regressions/ (crafted files that once crashed or over-read) under the sanitizers.
# The corpus is seeded from scenes/, ../shared/scenes (files up to 1 MB, with their .bin files beside them) and
# the regressions, and kept in build/fuzz/corpus between runs; findings are written to build/fuzz/findings/.
# Exits 77 (skipped) when clang or its libFuzzer runtime is missing, non-zero on a finding.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
command -v clang++ >/dev/null && command -v clang >/dev/null || { echo "fuzz: clang or clang++ not found, skipped"; exit 77; }
echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long) { return 0; }' > /tmp/vkmc-fuzz-probe.cpp
clang++ -fsanitize=fuzzer /tmp/vkmc-fuzz-probe.cpp -o /tmp/vkmc-fuzz-probe 2>/dev/null ||
  { echo "fuzz: clang's libFuzzer runtime (libclang-rt-dev) not found, skipped"; exit 77; }
out=build/fuzz
cmake -S tools/fuzz -B "$out" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$out" -j"$(nproc)" >/dev/null
[[ $seconds == build ]] && exit 0
mkdir -p "$out/corpus" "$out/seeds" "$out/findings"
for f in scenes/*.gltf scenes/*/*.gltf scenes/*.bin scenes/*/*.bin ../shared/scenes/*/*.gltf ../shared/scenes/*/*.glb \
         ../shared/scenes/*/*.bin ../shared/scenes/*.gltf ../shared/scenes/*.glb ../shared/scenes/*.bin; do
  [[ -f $f && $(stat -c %s "$f") -le 1048576 ]] || continue
  case $f in *.bin) cp "$f" "$out/seeds/";; *) cp "$f" "$out/seeds/$(basename "$(dirname "$f")")-$(basename "$f")";; esac
done
cp tests/fuzz/regressions/* "$out/seeds/"
export VKMC_FUZZ_BASEDIR=$PWD/$out/seeds
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# First the crafted files that once crashed or over-read (tools/fuzz/make_regressions.py), each run once.
"$out/gltf_fuzzer" tests/fuzz/regressions/* 2>&1 | tail -n 3
"$out/gltf_fuzzer" "$out/corpus" "$out/seeds" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=4096 \
  -malloc_limit_mb=2048 -artifact_prefix="$out/findings/" -print_final_stats=1 "$@" 2>&1 | tail -n 25
