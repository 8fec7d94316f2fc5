#!/usr/bin/env bash
# dem_start_run.sh GRANPIPE PROJECT WORKDIR NAME FILE [--set ...]
# A short dem run (the two-sphere pipeline, gravity on, no analyzer) from FILE into
# WORKDIR/NAME, its frames saved: for dem_start_files.sh, which runs it under expect.
set -eu
exe=$1 project=$2 work=$3 name=$4 file=$5
shift 5
exec "$exe" "$project/pipelines/dem_speed_vs_error.json" --out "$work/$name" --quiet --no-report \
  --set "source.params.initial_file=$file" --set 'source.params.gravity=[0,0,-1]' \
  --set source.params.duration=0.01 --set source.params.save_every=20 \
  --set output.save_frames=true --set 'analyzers=[]' "$@"
