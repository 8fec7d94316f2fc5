#!/usr/bin/env bash
# file_size_limit.sh GRANPIPE EXPECT WORKDIR
# Under a file-size limit (ulimit -f) a write past it sent SIGXFSZ, which killed the run
# (exit 153, no message) and left its folder marked running. Now, at several limits: exit
# 2 and one line, no file under its final name, the folder marked failed.
set -eu
exe=$1 expect=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
for blocks in 4 40 100; do
  out=$work/run_$blocks
  said=$(ulimit -f "$blocks"; "$expect" 2 "^granpipe: .*(disk full|cannot (create|flush|write|close))" \
    -- "$exe" "$here/long_lattice.json" --quiet --no-report --set source.params.frames=4 \
       --set output.save_frames=true --out "$out") || { echo "$said"; exit 1; }
  echo "-- ulimit -f $blocks: $said"
  for final in frames.h5 results.h5 packing.scalars.csv; do
    [ ! -e "$out/$final" ] || { echo "FAIL: a failed run left $final"; exit 1; }
  done
  grep -q '"status":"failed"' "$out/.granpipe-run" || { echo "FAIL: not marked failed"; exit 1; }
done
echo "a file-size limit at every stage: one line, exit 2, marked failed"
