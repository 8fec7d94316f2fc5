#!/usr/bin/env bash
# Every tracked C++ file is laid out as .clang-format says. clang-format's layout changes
# between major versions, so the check runs with Debian 12's (14), which install-deps.sh
# brings; another version skips (exit 77) rather than fail on its own taste.
set -euo pipefail
source_dir=$1
format=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$format" ] || ! "$format" --version | grep -q 'version 14\.'; then
  echo "skipped: expected clang-format 14 (Debian 12's), found ${format:-none}"; exit 77
fi
cd "$source_dir"
report=$(git ls-files -z '*.cpp' '*.hpp' '*.h' | xargs -0 "$format" --dry-run 2>&1)
if [ -n "$report" ]; then
  head -20 <<<"$report"
  echo "expected the layout of .clang-format, found $(grep -c 'warning:' <<<"$report") places that differ;" \
       "run: git ls-files '*.cpp' '*.hpp' '*.h' | xargs clang-format -i"
  exit 1
fi
echo "$(git ls-files '*.cpp' '*.hpp' '*.h' | wc -l) C++ files follow .clang-format"
