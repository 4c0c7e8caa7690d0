#!/usr/bin/env bash
# The whole test suite: install what is missing, build, run every ctest (extra arguments go to ctest,
# e.g. -L gpu). Shared models in ../shared/scenes are used when present and skipped otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cd build
ctest --output-on-failure --timeout 1200 "$@"
