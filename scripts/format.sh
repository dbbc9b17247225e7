#!/usr/bin/env bash
# clang-format over the C++ sources: `bash scripts/format.sh` checks (non-zero exit on a diff),
# `bash scripts/format.sh --fix` rewrites the files in place.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

clang_format=${CLANG_FORMAT:-clang-format}
mapfile -t files < <(git ls-files '*.hpp' '*.cpp')
if [ ${#files[@]} -eq 0 ]; then
  echo "==> [format] no C++ files"
  exit 0
fi
if [ "${1:-}" = "--fix" ]; then
  echo "==> [format] $clang_format -i (${#files[@]} files)"
  "$clang_format" -i "${files[@]}"
else
  echo "==> [format] $clang_format --dry-run --Werror (${#files[@]} files)"
  "$clang_format" --dry-run --Werror "${files[@]}"
fi
