#!/bin/bash
# Whether every C++ source keeps the layout of .clang-format (ctest sources-formatted). The layout is
# clang-format 14's (Debian 12's); another version lays some lines out differently, so without 14 the
# check is skipped (exit 77) rather than failed. --fix rewrites the files instead of checking them.
#   bash scripts/check_formatting.sh [--fix]
set -euo pipefail
cd "$(dirname "$0")/.."
formatter=$(command -v clang-format-14 || true)
if [[ -z "$formatter" ]]; then
  echo "clang-format-14 not found: the layout check is skipped (apt-get install clang-format-14)"
  exit 77
fi
# The sources: tracked files in a clone, every file otherwise (an unpacked archive). Generated tables
# carry their own .clang-format that turns formatting off.
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find . \( -path "./build*" -o -name node_modules \) -prune -o \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print)
fi
if [[ "${1:-}" == "--fix" ]]; then
  printf '%s\n' "${files[@]}" | xargs -n 50 "$formatter" -i --style=file
  exit 0
fi
if ! printf '%s\n' "${files[@]}" | xargs -n 50 "$formatter" --dry-run -Werror --style=file 2> /tmp/sphdeck-format-check.$$; then
  grep -m 20 'error:' /tmp/sphdeck-format-check.$$ || true
  rm -f /tmp/sphdeck-format-check.$$
  echo "some sources are not laid out as .clang-format says: bash scripts/check_formatting.sh --fix"
  exit 1
fi
rm -f /tmp/sphdeck-format-check.$$
echo "${#files[@]} sources laid out as .clang-format says"
