#!/usr/bin/env bash
# Runs the LIGGGHTS and LAMMPS inputs of this folder again and checks that they write the
# committed data-samples/*_bed*.dump.gz byte for byte (both runs are serial and
# deterministic). Skipped (exit 77) where the Debian packages liggghts and lammps are absent.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
for program in liggghts lmp; do
  if ! command -v "$program" > /dev/null; then
    echo "skipped: $program is not installed (apt-get install liggghts lammps)"
    exit 77
  fi
done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$here/make_samples.sh" "$out" > /dev/null
status=0
for f in liggghts_bed liggghts_bed_pairs liggghts_bed_walls lammps_bed lammps_bed_pairs; do
  if ! cmp -s "$out/$f.dump.gz" "$here/../../data-samples/$f.dump.gz"; then
    echo "data-samples/$f.dump.gz: expected what tests/lammps_runs writes, got another file"
    status=1
  fi
done
[ $status -eq 0 ] && echo "the 5 LIGGGHTS and LAMMPS samples are what their inputs write"
exit $status
