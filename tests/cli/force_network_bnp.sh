#!/usr/bin/env bash
# force_network_bnp.sh GRANPIPE SOURCE_DIR WORKDIR
# force_network from the command line on the settled Brazil-nut packing of data-samples/
# (which carries no contacts: one DEM step gives them): the run succeeds, streams one row per
# frame, reports the paper's frame with its fit status, PDF and F(r), and publishes its
# columns into frames.h5.
set -euo pipefail
exe=$1 src=$2 work=$3
mkdir -p "$work"
cat >"$work/force_network_bnp.json" <<JSON
{"source": {"plugin": "dem",
            "params": {"initial_file": "$src/data-samples/bnp_settled.h5",
                       "species": [{"name": "small", "density": 1.91}, {"name": "large", "density": 13.54}],
                       "walls": {"mu": 0.5},
                       "drive": {"form": "one_minus_cos", "amplitude": 7.5, "frequency": 0.107},
                       "dt": 2e-4, "duration": 2e-4, "save_every": 1}},
 "analyzers": [{"plugin": "force_network"}],
 "output": {"frame_stride": 1}}
JSON
out="$work/out"
"$exe" "$work/force_network_bnp.json" --quiet --overwrite --out "$out"
fail() { echo "FAIL: $*"; exit 1; }
rows=$(grep -vc '^#' "$out/force_network.per_frame.csv")
[ "$rows" = 3 ] || fail "expected a header and 2 frames in force_network.per_frame.csv, got $rows lines"
# Every particle of the settled bed rests on others: one network holds nearly all of them.
awk -F, '!/^#/ && $1 == "0" { exit !($3 >= 1 && $4 > 7000) }' "$out/force_network.per_frame.csv" ||
  fail "frame 0 has no large force network: $(sed -n 3p "$out/force_network.per_frame.csv")"
grep -q '^paper_frame,0,' "$out/force_network.scalars.csv" || fail "paper_frame is not 0"
grep -q '^eq11_status,' "$out/force_network.scalars.csv" || fail "no eq11_status"
for table in pdf correlation; do
  [ -s "$out/force_network.$table.csv" ] || fail "no force_network.$table.csv"
done
if grep -qi nan "$out/force_network.per_frame.csv" "$out/force_network.pdf.csv"; then
  fail "NaN in the per-frame table or the PDF"
fi
columns=$("$exe" inspect "$out/frames.h5")
grep -q '^  strong ' <<<"$columns" || fail "frames.h5 has no strong contact column"
grep -q '^  network ' <<<"$columns" || fail "frames.h5 has no network column"
echo "force_network ran on the settled BNP packing after one DEM step"
