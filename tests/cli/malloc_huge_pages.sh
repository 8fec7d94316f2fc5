#!/usr/bin/env bash
# malloc_huge_pages.sh GRANPIPE WORKDIR
# granpipe runs itself again, as one process, with glibc's malloc on transparent huge pages
# (GLIBC_TUNABLES=glibc.malloc.hugetlb=1, which glibc reads at start only): the running
# program's environment holds the tunable; a user's other tunables stay (glibc 2.36 shows
# them alone there once it has read them all); a user who names it keeps it as given.
set -eu
exe=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"

# GLIBC_TUNABLES as the running granpipe holds it, started with "$@" before it.
tunables_of_a_run() {
  local out="$work/run$RANDOM"
  "$@" "$exe" "$here/long_lattice.json" --out "$out" --quiet &
  local pid=$!
  for _ in $(seq 1 300); do
    [ -e "$out" ] && break
    sleep 0.1
  done
  tr '\0' '\n' <"/proc/$pid/environ" | sed -n 's/^GLIBC_TUNABLES=//p'
  # The process keeps its name (ps, pgrep, top): "exe" after running /proc/self/exe.
  comm=$(cat "/proc/$pid/comm")
  [ "$comm" = "$(basename "$exe")" ] || echo "FAIL: the process is named '$comm'"
  kill -9 "$pid"
  wait "$pid" 2>/dev/null || true
}

# expect PATTERN COMMAND...: the run's GLIBC_TUNABLES matches the glob PATTERN.
expect() {
  local found
  found=$(tunables_of_a_run "${@:2}")
  case "$found" in *FAIL:*) echo "$found"; exit 1 ;; esac
  # shellcheck disable=SC2053
  [[ "$found" == $1 ]] || { echo "FAIL: ${*:2}: expected GLIBC_TUNABLES '$1', found '$found'"; exit 1; }
  echo "${*:2}: GLIBC_TUNABLES=$found"
}

expect "glibc.malloc.hugetlb=1" env -u GLIBC_TUNABLES
expect "glibc.malloc.mxfast=0*" env GLIBC_TUNABLES=glibc.malloc.mxfast=0
expect "glibc.malloc.hugetlb=0" env GLIBC_TUNABLES=glibc.malloc.hugetlb=0
