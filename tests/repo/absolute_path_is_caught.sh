#!/usr/bin/env bash
# The absolute-path check fails on a tree that holds one (so its passing on the repo means
# something), and passes on paths relative to the project root.
set -euo pipefail
python=$1 check=$2
tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT
# Built from pieces, so that this script itself holds no such path.
printf 'data from ../shared/bench/bnp\nsee "/%s/me/granpipe/out/results.h5"\n' home >"$tree/notes.md"
if out=$("$python" "$check" "$tree"); then
  echo "expected the check to fail on $tree/notes.md, it passed: $out"; exit 1
fi
grep -qF "notes.md:2: expected paths relative to the project root, found /$(echo home)/me/granpipe" <<<"$out" \
  || { echo "unexpected report: $out"; exit 1; }
printf 'data from ../shared/bench/bnp and $work/home/me\n' >"$tree/notes.md"
"$python" "$check" "$tree" >/dev/null || { echo "relative paths flagged"; exit 1; }
echo "absolute path caught, relative paths passed"
