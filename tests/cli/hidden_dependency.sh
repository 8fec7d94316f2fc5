#!/usr/bin/env bash
# hidden_dependency.sh SOURCE_DIR WORKDIR
# Builds the source tree a second time as on a machine without CGAL, Boost and GSL, with a
# fixture plugin that needs CGAL: the configure succeeds, says in one line that the fixture
# is left out, and so for each shipped plugin that DEPENDS on one of them; the core and
# every other shipped plugin build and load. Then configures (only) with the tests on and
# CGAL present but not Boost: what needs Boost is left out, not more.
set -euo pipefail
src=$1 work=$2
# The shipped plugins whose granpipe_add_plugin call names a DEPENDS (all of them are on
# CGAL, Boost or GSL): left out here, each with one message.
optional=()
for dir in "$src"/plugins/*/; do
  grep -Eq '^[[:space:]]*DEPENDS[[:space:]]' "$dir/CMakeLists.txt" && optional+=("$(basename "$dir")")
done
is_optional() { [[ " ${optional[*]} " == *" $1 "* ]]; }
# The "left out" lines of a configure log other than those of the optional plugins.
other_left_out() {
  local pattern="^granpipe: plugin (${optional[*]// /|}) left out: "
  grep "left out" "$1" | { if [ ${#optional[@]} -gt 0 ]; then grep -Ev "$pattern"; else cat; fi; } || true
}
build="$work/build"
mkdir -p "$work"
rm -f "$build/CMakeCache.txt" "$work/with-tests/CMakeCache.txt"  # configure afresh, keep objects
if ! cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
       -DGRANPIPE_BUILD_TESTS=OFF -DGRANPIPE_BUILD_BENCHMARKS=OFF \
       -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=ON -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON \
       -DCMAKE_DISABLE_FIND_PACKAGE_GSL=ON \
       -DGRANPIPE_EXTRA_PLUGIN_DIRS="$src/tests/cli/fixtures/needs_cgal" --no-warn-unused-cli \
       >"$work/configure.log" 2>&1; then
  echo "FAIL: configure without CGAL, Boost and GSL:"; cat "$work/configure.log"; exit 1
fi
grep -x "granpipe: plugin needs_cgal left out: CGAL not found" "$work/configure.log" >/dev/null ||
  { echo "FAIL: no message that needs_cgal is left out:"; cat "$work/configure.log"; exit 1; }
if [ "$(other_left_out "$work/configure.log")" != "granpipe: plugin needs_cgal left out: CGAL not found" ]; then
  echo "FAIL: expected needs_cgal and (${optional[*]}) left out:"; grep "left out" "$work/configure.log"; exit 1
fi
for plugin in "${optional[@]}"; do
  grep -q "^granpipe: plugin $plugin left out: " "$work/configure.log" ||
    { echo "FAIL: no message that $plugin is left out"; exit 1; }
done

# With the tests on, and CGAL present but not Boost (that CGAL needs): the configure still
# succeeds, needs_cgal and the tests that need Boost are left out (configured, not built).
if ! cmake -S "$src" -B "$work/with-tests" -G Ninja -DGRANPIPE_BUILD_BENCHMARKS=OFF \
       -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON -DCMAKE_DISABLE_FIND_PACKAGE_GSL=ON \
       -DGRANPIPE_EXTRA_PLUGIN_DIRS="$src/tests/cli/fixtures/needs_cgal" --no-warn-unused-cli \
       >"$work/with-tests.log" 2>&1; then
  echo "FAIL: configure with the tests without Boost and GSL:"; cat "$work/with-tests.log"; exit 1
fi
expected="granpipe: tests of plugin arches left out: Boost not found
granpipe: plugin needs_cgal left out: CGAL not found"
if [ "$(other_left_out "$work/with-tests.log")" != "$expected" ]; then
  echo "FAIL: expected only needs_cgal and the arches tests left out:"
  grep "left out" "$work/with-tests.log"; exit 1
fi
grep -q "^build test_packing:" "$work/with-tests/build.ninja" ||
  { echo "FAIL: test_packing is not configured without Boost and GSL"; exit 1; }
! grep -q "^build test_arches:" "$work/with-tests/build.ninja" ||
  { echo "FAIL: test_arches is configured without Boost"; exit 1; }

nice -n 10 cmake --build "$build" -j2 >"$work/build.log" 2>&1 ||
  { echo "FAIL: build without CGAL, Boost and GSL:"; tail -40 "$work/build.log"; exit 1; }
plugin_dir="$build/lib/granpipe/plugins"
for dir in "$src"/plugins/*/; do
  plugin=$(basename "$dir")
  if is_optional "$plugin"; then
    [ ! -e "$plugin_dir/granpipe_$plugin.so" ] || { echo "FAIL: $plugin was built"; exit 1; }
    continue
  fi
  [ -f "$plugin_dir/granpipe_$plugin.so" ] || { echo "FAIL: plugin $plugin not built"; exit 1; }
done
[ ! -e "$plugin_dir/granpipe_needs_cgal.so" ] || { echo "FAIL: needs_cgal was built"; exit 1; }
env -u GRANPIPE_PLUGIN_PATH "$build/bin/granpipe" plugins >"$work/plugins.txt" ||
  { echo "FAIL: the plugins built without CGAL, Boost and GSL do not load:"; cat "$work/plugins.txt"; exit 1; }
echo "configured and built without CGAL, Boost and GSL; needs_cgal left out with one message"
