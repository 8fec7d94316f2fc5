#!/bin/sh
# The tap3d_compaction pipeline at a toy size: exit 0, and the compaction analyzer's tables
# written for every sweep point. Usage: tap3d_compaction_tables.sh GRANPIPE PIPELINE OUTDIR
set -e
"$1" "$2" --set source.params.N=64 --set source.params.side=6 --set source.params.taps=3 \
  --quiet --overwrite --out "$3"
for point in 000 001 002; do
  for table in per_frame spectrum ageing ageing_fits eq3_phi_b eq3_phi_c eq4_z_mean scalars; do
    file="$3/point_$point.compaction.$table.csv"
    if [ ! -s "$file" ]; then
      echo "expected the table $file, found none"
      exit 1
    fi
  done
done
