#!/usr/bin/env bash
# plugin_search.sh GRANPIPE PLUGIN_DIR WORKDIR
# What the loader says about its search path: a plugin not found names the directories
# searched and GRANPIPE_PLUGIN_PATH; a directory on the path without plugins is named; a
# plugin name provided twice is reported, never dropped silently.
set -eu
exe=$1 plugins=$2 work=$3
rm -rf "$work"
mkdir -p "$work/empty" "$work/dup"
fail() { echo "FAIL: $*"; exit 1; }

# Not found: exit 2, one line naming the search path.
set +e
GRANPIPE_PLUGIN_PATH="$work/empty:$plugins" "$exe" describe lattise 2>"$work/err" >/dev/null
code=$?
set -e
[ "$code" -eq 2 ] || fail "exit $code for an unknown plugin, expected 2"
[ "$(wc -l <"$work/err")" -eq 2 ] || fail "expected a warning and the error, got: $(cat "$work/err")"
grep -q "^granpipe: warning: plugin directory $work/empty holds no granpipe_\*\.so plugin library$" "$work/err" ||
  fail "no warning for the empty directory: $(cat "$work/err")"
grep -q "^granpipe: describe: expected a plugin, got unknown \"lattise\" (did you mean \"lattice\"?); known: .*; searched $work/empty, $plugins.* (GRANPIPE_PLUGIN_PATH, then the plugins beside granpipe)$" "$work/err" ||
  fail "the unknown plugin's message does not name the search path: $(cat "$work/err")"

# The same plugin name from two libraries: the first on the path is used, the other named.
cp "$plugins/granpipe_lattice.so" "$work/dup/granpipe_lattice_copy.so"
GRANPIPE_PLUGIN_PATH="$work/dup:$plugins" "$exe" plugins 2>"$work/err" >"$work/out"
grep -q "^granpipe: warning: plugin \"lattice\" of $plugins/granpipe_lattice.so ignored: $work/dup/granpipe_lattice_copy.so, earlier on the search path, provides it$" "$work/err" ||
  fail "no warning for the plugin provided twice: $(cat "$work/err")"
grep -q "lattice of $plugins/granpipe_lattice.so (used: $work/dup/granpipe_lattice_copy.so)" "$work/out" ||
  fail "granpipe plugins does not list the ignored library: $(cat "$work/out")"
# A copy of every bundled plugin earlier on the path: one line for them all, with the count.
mkdir -p "$work/copies"
cp "$plugins"/granpipe_*.so "$work/copies/"
count=$(ls "$plugins"/granpipe_*.so | wc -l)
GRANPIPE_PLUGIN_PATH="$work/copies:$plugins" "$exe" plugins 2>"$work/err" >/dev/null
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "expected one warning for the copied plugins, got: $(cat "$work/err")"
grep -q "^granpipe: warning: $count plugins of $plugins ignored (.*lattice.*): the libraries of $work/copies, earlier on the search path, provide them$" "$work/err" ||
  fail "the copied plugins' warning: $(cat "$work/err")"
echo "search path named, empty directory and duplicate plugins reported"
