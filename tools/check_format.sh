#!/usr/bin/env bash
# Checks that every C and C++ source of the project is formatted as .clang-format says (the
# formatting is applied with `tools/check_format.sh --fix`). Exit 0 when all are, 1 with the
# files that are not, 77 (a ctest skip) when clang-format is absent.
# Usage: tools/check_format.sh [--fix] [ROOT]   (ROOT: the repository, by default this script's)
set -euo pipefail
fix=0
if [ "${1:-}" = --fix ]; then fix=1; shift; fi
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
if ! command -v clang-format >/dev/null; then
  echo "clang-format is not installed (Debian: clang-format); skipping the format check"
  exit 77
fi
mapfile -t files < <(find src include tests bench fuzz examples tools \
  \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.c' \) -not -path '*/data/*' -not -path '*/corpus/*' | sort)
if [ "$fix" = 1 ]; then
  clang-format -i --style=file "${files[@]}"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  clang-format --style=file --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  echo "FAIL: ${#bad[@]} file(s) differ from .clang-format (run tools/check_format.sh --fix):"
  printf '  %s\n' "${bad[@]}"
  exit 1
fi
echo "all ${#files[@]} C/C++ sources match .clang-format"
