#!/usr/bin/env bash
# Fails when a C++ file of the project (not third_party/) differs from what clang-format makes of it
# (.clang-format); lists the files. Exits 77 (skipped) where clang-format is not installed.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check_format: clang-format not installed, skipped"; exit 77; }
bad=()
while IFS= read -r f; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done < <(git ls-files '*.cpp' '*.h' '*.hpp' '*.cc' | grep -v '^third_party/')
if ((${#bad[@]})); then
  printf '%s\n' "${bad[@]}"
  echo "check_format: ${#bad[@]} file(s) differ from clang-format (run: clang-format -i FILE)" >&2
  exit 1
fi
echo "check_format: every C++ file matches .clang-format"
