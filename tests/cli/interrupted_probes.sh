#!/usr/bin/env bash
# interrupted_probes.sh GRANPIPE PIPELINES_DIR WORKDIR
# SIGTERM while pores throws 10^8 P0 probes at a frame: the run stops at once, marked
# interrupted (it went on probing for a minute, the frame in progress being all probes).
set -eu
exe=$1 pipelines=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
"$exe" "$pipelines/reprocess_pores.json" --quiet --no-report --out "$work/run" \
  --set 'analyzers[0].params.probes=100000000' &
pid=$!
sleep 3
kill -TERM "$pid"
# A hang check, not a timing: the stop comes within a few thousand probes.
for _ in $(seq 1 300); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
if kill -0 "$pid" 2>/dev/null; then
  kill -KILL "$pid"
  echo "FAIL: still probing 30 s after SIGTERM"
  exit 1
fi
status=0
wait "$pid" || status=$?
[ "$status" -eq 143 ] || { echo "FAIL: exit $status, expected 143"; exit 1; }
grep -q '"status":"interrupted"' "$work/run/.granpipe-run" || { echo "FAIL: not marked interrupted"; exit 1; }
echo "pores' probes stop on SIGTERM"
