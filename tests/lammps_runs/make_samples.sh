#!/usr/bin/env bash
# Runs the two small vibrated beds of this folder with the Debian packages' LIGGGHTS
# (liggghts) and LAMMPS (lmp) and writes their dumps, gzip-compressed, into data-samples/:
#   liggghts_bed.dump.gz, liggghts_bed_pairs.dump.gz, liggghts_bed_walls.dump.gz
#   lammps_bed.dump.gz, lammps_bed_pairs.dump.gz
# Usage: tests/lammps_runs/make_samples.sh [OUT_DIR]   (OUT_DIR: data-samples/ by default;
# the ctest data_samples_lammps_runs_unchanged writes elsewhere and compares)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
samples=$(cd "${1:-$here/../../data-samples}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here/in.liggghts_bed" "$here/plate.stl" "$here/in.lammps_bed" "$work/"
cd "$work"
liggghts -in in.liggghts_bed -log none -echo none > liggghts.out
lmp -in in.lammps_bed -log none -echo none > lammps.out
for f in liggghts_bed liggghts_bed_pairs liggghts_bed_walls lammps_bed lammps_bed_pairs; do
  gzip -n -9 -c "$f.dump" > "$samples/$f.dump.gz"
done
ls -l "$samples"/*_bed*.dump.gz
