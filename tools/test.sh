#!/usr/bin/env bash
# The whole test suite: install what is missing, build, run every ctest (extra arguments go to ctest,
# e.g. -L gpu). Shared models in ../shared/scenes are used when present and skipped otherwise. Tests run as many
# at a time as there are cores: each test's own work is partly serial (kernel compilation, BVH builds, the host's
# statistics), so the long furnace test and the rest share the machine instead of waiting for each other.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh --test-tools
bash tools/fuzz.sh build >/dev/null || true  # the fuzzer is built with the rest where clang is (skipped elsewhere)
cd build
ctest --output-on-failure --timeout 1200 -j"$(nproc)" "$@"
