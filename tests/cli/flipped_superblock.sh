#!/usr/bin/env bash
# flipped_superblock.sh GRANPIPE EXPECT SAMPLE.h5 WORKDIR
# One flipped bit in the superblock (version 3, checksummed: bytes 8 to 47) fails its
# checksum. The normal open refuses the file and the SWMR-read open retried for good:
# `inspect`, `validate` and a run of the h5md source must give the one-line message and
# exit 2. `timeout` turns a hang back into a failure rather than a stuck test.
set -eu
exe=$1 expect=$2 sample=$3 work=$4
rm -rf "$work"
mkdir -p "$work"

# flip_bit FILE BYTE BIT
flip_bit() {
  local value
  value=$(od -An -tu1 -j "$2" -N1 "$1" | tr -d ' ')
  printf "$(printf '\\%03o' $((value ^ (1 << $3))))" | dd of="$1" bs=1 seek="$2" conv=notrunc status=none
}

# The version byte, the end-of-file address and the checksum itself.
for byte in 8 28 44; do
  cp "$sample" "$work/flipped_$byte.h5"
  flip_bit "$work/flipped_$byte.h5" "$byte" 0
  "$expect" 2 "^granpipe: $work/flipped_$byte\.h5: not a readable HDF5 file \(truncated or corrupt\)$" \
    -- timeout 60 "$exe" inspect "$work/flipped_$byte.h5"
done

cat >"$work/reprocess.json" <<JSON
{"source": {"plugin": "h5md", "params": {"file": "$work/flipped_44.h5"}}, "output": {"dir": "$work/out"}}
JSON
"$expect" 2 "^granpipe: $work/reprocess\.json: source\.params\.file: $work/flipped_44\.h5: not a readable HDF5 file \(truncated or corrupt\)$" \
  -- timeout 60 "$exe" validate "$work/reprocess.json"
"$expect" 2 "^granpipe: $work/reprocess\.json: source\.params\.file: $work/flipped_44\.h5: not a readable HDF5 file \(truncated or corrupt\)$" \
  -- timeout 60 "$exe" run "$work/reprocess.json"
echo "flipped superblock bits refused"
