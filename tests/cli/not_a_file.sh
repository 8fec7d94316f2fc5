#!/usr/bin/env bash
# not_a_file.sh GRANPIPE SOURCE_DIR WORKDIR
# Paths where a file was expected and none stands are refused with exit 2 and one line saying
# what is there. A loop of symbolic links as a data file ended in an internal error (exit 1)
# and as a pipeline was called "no such file"; a pipe as a frames file or pipeline waits for
# a writer forever; a pipeline longer than the limit is refused without being read whole.
set -euo pipefail
exe=$1 src=$2 work=$3
expect=$(dirname "$0")/expect_error.sh
rm -rf "$work"
mkdir -p "$work"
cd "$work"
ln -s loop_b loop_a
ln -s loop_a loop_b
ln -s no_such_target dangling
mkfifo pipe
truncate -s 65M long.json
pores=$src/pipelines/reprocess_pores.json

"$expect" 2 '^granpipe: loop_a: expected a pipeline JSON file, got a loop of symbolic links$' -- "$exe" validate loop_a
"$expect" 2 '^granpipe: dangling: expected a pipeline JSON file, got a symbolic link to nothing \(no_such_target\)$' -- "$exe" validate dangling
"$expect" 2 '^granpipe: pipe: expected a pipeline JSON file, got no regular file \(a pipe, socket or device\)$' -- "$exe" validate pipe
"$expect" 2 '^granpipe: long\.json: expected a pipeline JSON file of at most 64 MB, got a longer one$' -- "$exe" validate long.json
"$expect" 2 '^granpipe: --set source\.params\.file=loop_a: expected an existing file, got "loop_a" \(a loop of symbolic links\)$' \
  -- "$exe" validate "$pores" --set source.params.file=loop_a
"$expect" 2 '^granpipe: loop_a: expected an HDF5 file, got a loop of symbolic links$' -- "$exe" inspect loop_a
"$expect" 2 '^granpipe: pipe: expected an HDF5 file, got no regular file \(a pipe, socket or device\)$' -- "$exe" inspect pipe
"$expect" 2 "^granpipe: loop_a: expected a run's output directory, got a loop of symbolic links$" -- "$exe" report loop_a
