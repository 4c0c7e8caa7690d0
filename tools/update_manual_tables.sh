#!/usr/bin/env bash
# Rewrites the tables of docs/manual that are made from the code's own tables (tools/manual_tables/main.cpp).
# Run after changing an estimator parameter or the glTF extension table; the `style` test checks them.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build --target vkmc-manual-tables >/dev/null
./build/vkmc-manual-tables --update docs/manual
