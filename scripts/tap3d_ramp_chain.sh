#!/bin/sh
# Fig. 4's ramp at the paper's size (N = 4096, L = 32 R, 4000 taps a step: 172 000 taps) is
# one chain that cannot be split into independent runs and takes far longer than a session.
# It runs in parts, each started from the last frame the part before saved. The parts' frames
# are kept in the repository (docs/data/tap3d_ramp4000/partNN.h5) because a session's machine
# does not outlive it: a chain kept outside was lost with one.
#
#   scripts/tap3d_ramp_chain.sh run    start the next part in out/tap3d_ramp4000_partNN
#                                      (stop it with SIGTERM; up to save_every taps are lost)
#   scripts/tap3d_ramp_chain.sh keep   copy what that part saved into the chain
#   scripts/tap3d_ramp_chain.sh files  the chain's parts in order (for h5md's continued_in)
set -eu

chain=docs/data/tap3d_ramp4000
granpipe=${GRANPIPE:-build/bin/granpipe}
cd "$(dirname "$0")/.."
mkdir -p "$chain"

parts() { ls "$chain"/part[0-9][0-9].h5 2>/dev/null || true; }
count=$(parts | wc -l)
next=$(printf 'part%02d' $((count + 1)))
out=out/tap3d_ramp4000_$next

case "${1:-}" in
run)
  start=""
  if [ "$count" -gt 0 ]; then
    start="--set source.params.initial_file=$(parts | tail -n 1) --set source.params.continue_count=true"
  fi
  # shellcheck disable=SC2086  # $start is two words or none
  exec "$granpipe" pipelines/tap3d_hysteresis.json --out "$out" --no-report \
    --set source.params.N=4096 --set source.params.side=32 \
    --set source.params.ramp_root_min=0.05 --set source.params.ramp_root_step=0.025 \
    --set source.params.ramp_taps_per_step=4000 --set source.params.save_every=1000 \
    --set source.params.eta=1e-7 --set output.save_frames=true $start
  ;;
keep)
  saved=$out/frames.h5
  [ -f "$saved" ] || saved=$out/frames.partial.h5
  [ -f "$saved" ] || { echo "$0: $out holds no frames to keep" >&2; exit 2; }
  cp "$saved" "$chain/$next.h5"
  # A part stopped by a signal may leave its file marked open for writing.
  h5clear -s "$chain/$next.h5"
  echo "$chain/$next.h5"
  ;;
files)
  parts
  ;;
*)
  echo "usage: $0 run|keep|files" >&2
  exit 2
  ;;
esac
