#!/usr/bin/env bash
# Checks that the C++ sources follow .clang-format (`make format` rewrites them so).
# Usage: check-format.sh SOURCE_DIR [--fix]. Exit 77 (a skip for CTest) without clang-format.
set -euo pipefail
root=$1
command -v clang-format > /dev/null || { echo "clang-format is not installed"; exit 77; }
mapfile -t files < <(cd "$root" && find src tests python bench fuzz -name '*.cpp' -o -name '*.h' | sort)
cd "$root"
if [ "${2:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
else
  clang-format --dry-run --Werror "${files[@]}"
fi
