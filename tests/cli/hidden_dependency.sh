#!/usr/bin/env bash
# hidden_dependency.sh SOURCE_DIR WORKDIR
# Builds the source tree a second time as on a machine without CGAL, Boost and GSL, with a
# fixture plugin that needs CGAL: the configure succeeds, says in one line that the fixture
# is left out (and each shipped plugin that needs them), and the core and every other
# shipped plugin build and load. Then configures (only)
# with the tests on and CGAL present but not Boost: what needs Boost is left out, not more.
set -euo pipefail
src=$1 work=$2
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
# Shipped plugins that declare dependencies of their own (DEPENDS in their CMakeLists.txt,
# e.g. mst: Boost.Graph and CGAL) are left out too, each with one message; no other is.
own_dependencies() { grep -Eq '^[[:space:]]*DEPENDS' "$src/plugins/$1/CMakeLists.txt" 2>/dev/null; }
without_own() {
  grep "left out" "$1" | while read -r line; do
    plugin=$(sed -n 's/^granpipe: plugin \([a-z0-9_]*\) left out: .*$/\1/p' <<<"$line")
    [ -n "$plugin" ] && own_dependencies "$plugin" || echo "$line"
  done
}
if [ "$(without_own "$work/configure.log")" != "granpipe: plugin needs_cgal left out: CGAL not found" ]; then
  echo "FAIL: expected only needs_cgal and plugins with dependencies of their own left out:"
  grep "left out" "$work/configure.log"; exit 1
fi

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
if [ "$(without_own "$work/with-tests.log")" != "$expected" ]; then
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
  if own_dependencies "$plugin"; then continue; fi
  [ -f "$plugin_dir/granpipe_$plugin.so" ] || { echo "FAIL: plugin $plugin not built"; exit 1; }
done
[ ! -e "$plugin_dir/granpipe_needs_cgal.so" ] || { echo "FAIL: needs_cgal was built"; exit 1; }
env -u GRANPIPE_PLUGIN_PATH "$build/bin/granpipe" plugins >"$work/plugins.txt" ||
  { echo "FAIL: the plugins built without CGAL, Boost and GSL do not load:"; cat "$work/plugins.txt"; exit 1; }
echo "configured and built without CGAL, Boost and GSL; needs_cgal left out with one message"
