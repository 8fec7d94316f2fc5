#!/usr/bin/env bash
# make_seed_corpus.sh GRANPIPE SOURCE_DIR OUT [WRITE_SAMPLE_FRAMES]
# Seed corpora for the fuzzers (docs/fuzzing.md):
# - OUT/pipeline: the shipped pipelines, and some with --set values after NUL bytes, as
#   fuzz_pipeline splits its input;
# - OUT/frames: the sample files, small frames.h5 files of the lattice and disks2d_tap
#   sources, the layout samples of tests/python (contacts, a cylinder) when its writer is
#   given, other tools' files when h5py is there, and contiguous copies of them all
#   (h5repack), a few kilobytes each, which the fuzzer mutates faster.
set -eu
exe=$1 src=$2 out=$3 sample_writer=${4:-}
rm -rf "$out"
mkdir -p "$out/pipeline" "$out/frames" "$out/work"

for p in "$src"/pipelines/*.json; do cp "$p" "$out/pipeline/"; done
with_sets() {  # with_sets NAME PIPELINE SET...
  local name=$1 pipeline=$2
  shift 2
  { cat "$src/pipelines/$pipeline"; for s in "$@"; do printf '\0%s' "$s"; done; } >"$out/pipeline/$name"
}
with_sets lattice_sets lattice_packing.json 'source.params.cells=[2,2,2]' 'analyzers[0].params.tolerance=1e-6'
with_sets tap2d_sets tap2d_arches.json 'source.params.N=100' 'sweep.mode=zip'
with_sets reprocess_sets reprocess_fcc_sample.json 'source.params.stride=2' 'seed=7' 'name=again'

for f in "$src"/data-samples/*.h5; do cp "$f" "$out/frames/"; done
cat >"$out/work/lattice.json" <<JSON
{"source": {"plugin": "lattice", "params": {"lattice": "sc", "cells": [2, 1, 1], "jitter": 0.1, "frames": 2}}}
JSON
cat >"$out/work/disks.json" <<JSON
{"source": {"plugin": "disks2d_tap",
            "params": {"width": 4, "N": 6, "equilibration_taps": 0, "production_taps": 2, "save_every": 1}}}
JSON
for run in lattice disks; do
  "$exe" run "$out/work/$run.json" --quiet --out "$out/work/$run"
  cp "$out/work/$run/frames.h5" "$out/frames/$run.h5"
done
if [ -n "$sample_writer" ]; then
  "$sample_writer" "$out/work/samples" >/dev/null
  cp "$out/work/samples/"*.h5 "$out/frames/"
fi
if /usr/bin/python3 -c "import h5py" 2>/dev/null; then
  /usr/bin/python3 "$src/tests/cli/make_bad_particles.py" "$out/work"
  for f in overlapping nan; do cp "$out/work/$f.h5" "$out/frames/foreign_$f.h5"; done
fi
if command -v h5repack >/dev/null; then
  for f in "$out"/frames/*.h5; do h5repack -l CONTI "$f" "${f%.h5}_contiguous.h5"; done
fi
rm -rf "$out/work"
echo "seed corpora in $out: $(ls "$out/pipeline" | wc -l) pipelines, $(ls "$out/frames" | wc -l) frames files"
