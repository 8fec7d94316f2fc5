#!/usr/bin/env bash
# corrupt_hdf5.sh GRANPIPE EXPECT SAMPLE.h5 WORKDIR
# A truncated HDF5 file and a file that is not HDF5 at all, given to `inspect` and to
# a reprocessing pipeline: exit 2 with one line naming the file.
set -eu
exe=$1 expect=$2 sample=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
size=$(stat -c %s "$sample")
head -c $((size / 2)) "$sample" >"$work/truncated.h5"
echo "this is not HDF5" >"$work/text.h5"
cat >"$work/reprocess.json" <<JSON
{"source": {"plugin": "h5md", "params": {"file": "$work/truncated.h5"}}, "output": {"dir": "$work/out"}}
JSON
"$expect" 2 "truncated\.h5: .*(corrupt|truncated)" -- "$exe" inspect "$work/truncated.h5"
"$expect" 2 "text\.h5: .*(not|corrupt)" -- "$exe" inspect "$work/text.h5"
"$expect" 2 "truncated\.h5: .*(corrupt|truncated)" -- "$exe" "$work/reprocess.json"
"$expect" 2 "missing\.h5: " -- "$exe" inspect "$work/missing.h5"
[ ! -e "$work/out/results.h5" ] || { echo "FAIL: a failed run left results.h5"; exit 1; }
echo "all corrupt-input cases rejected"
