#!/usr/bin/env bash
# concurrent_runs.sh GRANPIPE SHORT_PIPELINE WORKDIR
# Two runs started at once into one --out: one wins, the other is refused with exit 2,
# and every file of the directory comes from the winner. The same for two --overwrite
# runs replacing one earlier run, which stays whole until the winner is complete.
set -eu
exe=$1 short=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"

# from_run DIR SEED PID: every file of DIR that records a seed or a process has these.
from_run() {
  local dir=$1 seed=$2 pid=$3
  grep -q "\"seed\": $seed," "$dir/pipeline.json" || { echo "FAIL: $dir/pipeline.json is not the winner's"; exit 1; }
  grep -q ", seed $seed, " "$dir/run.log" || { echo "FAIL: $dir/run.log is not the winner's"; exit 1; }
  [ "$(grep -c '^granpipe ' "$dir/run.log")" -eq 1 ] || { echo "FAIL: $dir/run.log has two runs"; exit 1; }
  grep -q "\"pid\":$pid," "$dir/.granpipe-run" || { echo "FAIL: $dir/.granpipe-run is not the winner's"; exit 1; }
  for csv in "$dir"/*.csv; do
    grep -q "^# .* seed $seed$" "$csv" || { echo "FAIL: $csv is not the winner's"; exit 1; }
  done
}

# One winner, one refusal, whatever the timing: a loser that comes late finds the
# winner's finished run, which it may not reuse without --overwrite.
for round in 1 2 3 4 5; do
  out=$work/race$round
  "$exe" "$short" --quiet --set seed=1 --out "$out" 2>"$work/err1" & pid1=$!
  "$exe" "$short" --quiet --set seed=2 --out "$out" 2>"$work/err2" & pid2=$!
  code1=0 code2=0
  wait "$pid1" || code1=$?
  wait "$pid2" || code2=$?
  case "$code1 $code2" in
    "0 2") winner=1 pid=$pid1 loser=$work/err2 ;;
    "2 0") winner=2 pid=$pid2 loser=$work/err1 ;;
    *) echo "FAIL: round $round: exit codes $code1 and $code2"; cat "$work/err1" "$work/err2"; exit 1 ;;
  esac
  [ "$(wc -l <"$loser")" -eq 1 ] && grep -Eq "^granpipe: $out: (another granpipe run|expected a new or empty output directory)" "$loser" ||
    { echo "FAIL: round $round: the loser said: $(cat "$loser")"; exit 1; }
  from_run "$out" "$winner" "$pid"
  [ -z "$(compgen -G "$out.granpipe-*")" ] || { echo "FAIL: round $round left a directory beside $out"; exit 1; }
  echo "round $round: run $winner won; $(cat "$loser")"
done

# Two replacing runs of one earlier run, long enough that both are still starting when
# the first claims it: the loser is refused, the winner is stopped, the earlier run is whole.
earlier=$work/race1
sum() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 md5sum); }
sum "$earlier" >"$work/earlier.sum"
"$exe" "$here/long_lattice.json" --quiet --set seed=3 --out "$earlier" --overwrite 2>"$work/err1" & pid1=$!
"$exe" "$here/long_lattice.json" --quiet --set seed=4 --out "$earlier" --overwrite 2>"$work/err2" & pid2=$!
while kill -0 "$pid1" 2>/dev/null && kill -0 "$pid2" 2>/dev/null; do sleep 0.1; done
if kill -0 "$pid1" 2>/dev/null; then running=$pid1 done_pid=$pid2 loser=$work/err2; else running=$pid2 done_pid=$pid1 loser=$work/err1; fi
code=0
wait "$done_pid" || code=$?
[ "$code" -eq 2 ] || { echo "FAIL: the first replacing run to end exited $code: $(cat "$loser")"; exit 1; }
grep -q "^granpipe: $earlier: another granpipe run is writing or replacing this output directory" "$loser" ||
  { echo "FAIL: the loser said: $(cat "$loser")"; exit 1; }
kill -TERM "$running"
wait "$running" || true
sum "$earlier" | cmp -s - "$work/earlier.sum" || { echo "FAIL: the replacing runs changed the earlier run"; exit 1; }
[ "$(compgen -G "$earlier.granpipe-new-*" | wc -l)" -eq 1 ] || { echo "FAIL: not one new directory beside"; exit 1; }
echo "concurrent runs: one winner each time, never a directory of two runs"
