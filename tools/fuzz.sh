#!/usr/bin/env bash
# Fuzzes vkmc's readers with libFuzzer (clang, ASan, UBSan): the glTF loader and the BVH build (gltf_fuzzer), the
# glTF image decoder (image_fuzzer), the Radiance .hdr reader (radiance_fuzzer), the OpenEXR reader (exr_fuzzer)
# and the checkpoint reader (checkpoint_fuzzer).
#   bash tools/fuzz.sh [SECONDS] [extra flags]   the glTF harness SECONDS (default 60), each other a quarter of it
#   bash tools/fuzz.sh runs N                     every harness N executions (the figure in docs/results.md)
#   bash tools/fuzz.sh build                      only builds the harnesses (tools/test.sh does, so a run is a run)
# First it replays tests/fuzz/regressions/ (crafted files that once crashed or over-read) under the sanitizers.
# The glTF corpus is seeded from scenes/, ../shared/scenes (files up to 1 MB, with their .bin files beside them),
# the regressions and tools/fuzz/make_gltf_seeds.cpp (Draco, meshopt, embedded PNG, JPEG and WebP); the readers' from tools/fuzz/make_seeds.py, small images of the scenes, the KTX2 test textures and a small EXR.
# Corpora stay in build/fuzz/corpus-HARNESS between runs; findings go to build/fuzz/findings/. A hang is an input
# that used more than its CPU time (tools/fuzz/cpu_timeout.h), so a busy machine gives no false timeouts.
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
if [[ $seconds == runs ]]; then
  budget=(-runs="${1:?runs needs a count}") readerBudget=(-runs="$1")
  shift
else
  budget=(-max_total_time="$seconds") readerBudget=(-max_total_time="$((seconds / 4 > 5 ? seconds / 4 : 5))")
fi
mkdir -p "$out/corpus-gltf" "$out/seeds" "$out/findings"
for f in scenes/*.gltf scenes/*/*.gltf scenes/*.bin scenes/*/*.bin ../shared/scenes/*/*.gltf ../shared/scenes/*/*.glb \
         ../shared/scenes/*/*.bin ../shared/scenes/*.gltf ../shared/scenes/*.glb ../shared/scenes/*.bin; do
  [[ -f $f && $(stat -c %s "$f") -le 1048576 ]] || continue
  case $f in *.bin) cp "$f" "$out/seeds/";; *) cp "$f" "$out/seeds/$(basename "$(dirname "$f")")-$(basename "$f")";; esac
done
cp tests/fuzz/regressions/*.gltf tests/fuzz/regressions/*.glb "$out/seeds/"
# Draco, meshopt and embedded PNG, JPEG and WebP images (tools/fuzz/make_gltf_seeds.cpp, built with the tests).
if [[ -x build/vkmc-fuzz-seeds ]]; then build/vkmc-fuzz-seeds "$out/seeds" "$out/reader-seeds/image_fuzzer"; else echo "fuzz: build/vkmc-fuzz-seeds not built: no Draco, meshopt or embedded-image seeds"; fi
export VKMC_FUZZ_BASEDIR=$PWD/$out/seeds
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# -timeout (wall time) only as a backstop: the harnesses time an input by its CPU time.
common=(-timeout=600 -rss_limit_mb=4096 -malloc_limit_mb=2048 -artifact_prefix="$out/findings/" -print_final_stats=1)
# First the crafted files that once crashed or over-read (tools/fuzz/make_regressions.py), each run once.
"$out/gltf_fuzzer" tests/fuzz/regressions/*.gltf tests/fuzz/regressions/*.glb 2>&1 | tail -n 3
"$out/image_fuzzer" tests/fuzz/regressions/images/* 2>&1 | tail -n 1
echo "fuzz: gltf_fuzzer"
"$out/gltf_fuzzer" "$out/corpus-gltf" "$out/seeds" "${budget[@]}" -max_len=65536 "${common[@]}" "$@" 2>&1 | tail -n 25
# The readers: seeds of their own (the image harness's PNG, JPEG and WebP from vkmc-fuzz-seeds above).
python3 tools/fuzz/make_seeds.py "$out/reader-seeds"
mkdir -p "$out/reader-seeds/exr_fuzzer"
find scenes ../shared/scenes -maxdepth 3 \( -name '*.png' -o -name '*.jpg' \) -size -256k 2>/dev/null | head -n 8 |
  while read -r f; do cp "$f" "$out/reader-seeds/image_fuzzer/"; done
cp tests/unit/data/ktx2/*.ktx2 "$out/reader-seeds/image_fuzzer/"  # ETC1S and UASTC (Basis Universal's encoder)
if [[ -x build/vkmc ]]; then
  build/vkmc render scenes/cornell_box.gltf --width 8 --height 8 --spp 2 -q -o "$out/reader-seeds/exr_fuzzer/small.exr" \
    >/dev/null 2>&1 || true
fi
for harness in image_fuzzer radiance_fuzzer exr_fuzzer checkpoint_fuzzer; do
  [[ -x $out/$harness ]] || continue
  mkdir -p "$out/corpus-$harness" "$out/reader-seeds/$harness"
  echo "fuzz: $harness"
  "$out/$harness" "$out/corpus-$harness" "$out/reader-seeds/$harness" "${readerBudget[@]}" -max_len=16384 "${common[@]}" \
    2>&1 | tail -n 4
done
