#!/usr/bin/env bash
# interrupted_marker.sh GRANPIPE EXPECT WORKDIR
# SIGINT and SIGTERM end a run with their usual status (130, 143), and now run.log and
# the directory's marker say the run was interrupted, and its frames.partial.h5 and
# results.partial.h5 are closed files (no SWMR needed); a SIGKILLed run's marker still
# says running. Reusing such a directory is refused with the way to rerun
# (--overwrite). A replacing run that is interrupted leaves the earlier run whole.
set -eu
set -m  # background runs take SIGINT as a foreground run would, instead of ignoring it
exe=$1 expect=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
long=$here/long_lattice.json
rm -rf "$work"
mkdir -p "$work"

# start_long OUT [ARGS...]: starts a long run and waits until it writes frames.
start_long() {
  "$exe" "$long" --quiet --out "$@" 2>"$work/stderr" &
  pid=$!
  for _ in $(seq 1 600); do
    compgen -G "$1*/frames.partial.h5" >/dev/null && return
    sleep 0.1
  done
  echo "FAIL: the run wrote no frames in 60 s"
  exit 1
}
# stop SIGNAL CODE: sends SIGNAL to the run started last and checks its exit status.
stop() {
  kill "-$1" "$pid"
  local code=0
  wait "$pid" || code=$?
  [ "$code" -eq "$2" ] || { echo "FAIL: exit status $code after SIG$1, expected $2"; exit 1; }
}
status_is() {  # status_is DIR STATUS
  grep -q "\"status\":\"$2\"" "$1/.granpipe-run" || { echo "FAIL: $1 is not marked $2: $(cat "$1/.granpipe-run")"; exit 1; }
}
last_log_line_is() {  # last_log_line_is DIR LINE
  [ "$(tail -n 1 "$1/run.log")" = "$2" ] || { echo "FAIL: $1/run.log ends with \"$(tail -n 1 "$1/run.log")\""; exit 1; }
}

for signal in INT:130 TERM:143; do
  name=${signal%:*} code=${signal#*:}
  out=$work/sig$name
  start_long "$out"
  stop "$name" "$code"
  status_is "$out" interrupted
  last_log_line_is "$out" "interrupted by SIG$name before the run finished"
  # Stopped in order, the run closed its files: they open without SWMR.
  /usr/bin/python3 - "$out" <<'PY' || { echo "FAIL: the files of the run stopped by SIG$name"; exit 1; }
import sys, h5py
out = sys.argv[1]
for name in ("frames.partial.h5", "results.partial.h5"):
    with h5py.File(f"{out}/{name}", "r") as f:  # no swmr=True
        complete = f["granpipe"].attrs["complete"] if name.startswith("frames") else f.attrs["complete"]
        assert int(complete) == 0, f"{name} of an interrupted run must say it is incomplete"
with h5py.File(f"{out}/frames.partial.h5", "r") as f:
    assert len(f["particles/all/position/value"]) >= 1, "no frame kept"
PY
  [ "$(cat "$work/stderr")" = "granpipe: interrupted by SIG$name; $out is marked interrupted (rerun with --overwrite)" ] ||
    { echo "FAIL: stderr after SIG$name: $(cat "$work/stderr")"; exit 1; }
  "$expect" 2 "sig$name: expected a new or empty output directory, got one holding an interrupted run; pass --overwrite to replace it" \
    -- "$exe" "$long" --quiet --out "$out"
done

# The report of a stopped run linked the CSVs of its long tables, which a run writes only
# when it ends.
out=$work/reported
start_long "$out"
sleep 1  # hundreds of frames: more rows than the report shows
stop TERM 143
"$exe" report "$out" 2>/dev/null
grep -q 'every row in results.partial.h5 (the CSVs are written when the run ends)' "$out/report.html" ||
  { echo "FAIL: the report of a stopped run does not say where its long tables are"; exit 1; }
if grep -q 'href="packing.per_frame.csv"' "$out/report.html"; then
  echo "FAIL: the report of a stopped run links a CSV the run did not write"
  exit 1
fi

out=$work/killed
start_long "$out"
stop KILL 137
status_is "$out" running
"$expect" 2 "killed: expected a new or empty output directory, got one holding a run that stopped before it finished \(killed\?\); pass --overwrite" \
  -- "$exe" "$long" --quiet --out "$out"
"$exe" "$long" --quiet --set source.params.frames=2 --out "$out" --overwrite
status_is "$out" complete

# Interrupting a replacing run: the earlier run is untouched, the new one beside it says why.
earlier=$work/killed
sum() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 md5sum); }
sum "$earlier" >"$work/earlier.sum"
start_long "$earlier" --overwrite
stop INT 130
sum "$earlier" | cmp -s - "$work/earlier.sum" || { echo "FAIL: an interrupted --overwrite changed the earlier run"; exit 1; }
beside=$(compgen -G "$earlier.granpipe-new-*")
status_is "$beside" interrupted
grep -q "^granpipe: interrupted by SIGINT; the earlier run in $earlier is untouched; this one is in $beside, marked interrupted$" "$work/stderr" ||
  { echo "FAIL: stderr: $(cat "$work/stderr")"; exit 1; }
# stopped_inside NAME WHAT: runs $work/NAME.json, sends SIGTERM 2 s after it starts (inside
# one long frame) and checks that the run ends within 10 s, interrupted.
stopped_inside() {
  local out=$work/$1 code=0
  "$exe" "$work/$1.json" --quiet --out "$out" 2>"$work/stderr" &
  pid=$!
  for _ in $(seq 1 100); do [ -f "$out/run.log" ] && break; sleep 0.1; done
  sleep 2  # into the long frame (the wide bed's deposition alone takes longer than 10 s)
  kill -TERM "$pid"
  timeout 10 tail --pid="$pid" -f /dev/null || { echo "FAIL: SIGTERM left $2 running 10 s"; kill -9 "$pid"; exit 1; }
  wait "$pid" || code=$?
  [ "$code" -eq 143 ] || { echo "FAIL: exit status $code after SIGTERM inside $2, expected 143"; exit 1; }
  status_is "$out" interrupted
}
# A source whose one frame takes minutes (a tap of a bed 60000 disks wide) looks for the
# signal in its loops: SIGTERM waited for the frame's end (an hour with 10^5 disks).
cat >"$work/wide.json" <<'JSON'
{"name": "wide", "source": {"plugin": "disks2d_tap", "params": {"width": 60000, "N": 60000,
 "protocol": "constant", "A": 1.1, "equilibration_taps": 1, "production_taps": 1, "save_every": 1}}}
JSON
stopped_inside wide "the source"
# One check of a tap's redeposition can hold 1e10 trials (minutes): check_moves 1e15 ended
# none, and the first SIGTERM waited for ever.
cat >"$work/endless.json" <<'JSON'
{"name": "endless", "source": {"plugin": "spheres3d_tap", "params": {"N": 60, "side": 6,
 "taps": 1, "check_moves": 10000000000}}}
JSON
stopped_inside endless "the tap"
echo "interruptions recorded in run.log and the marker; the earlier run kept whole; a long frame stopped"
