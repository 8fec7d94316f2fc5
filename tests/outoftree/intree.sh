#!/usr/bin/env bash
# intree.sh SOURCE_DIR WORKDIR
# Configures granpipe with the out-of-tree example's folder as an extra plugin folder and
# only the lattice plugin selected: the folder's plugins must be in the build (its
# find_package skipped inside the tree, the selection not applied to a folder named
# explicitly). Configured only: outoftree.sh builds and runs the same plugins.
set -euo pipefail
src=$1 work=$2
rm -rf "$work" "$work.log"
cmake -S "$src" -B "$work" -G Ninja -DGRANPIPE_PLUGINS=lattice \
      -DGRANPIPE_EXTRA_PLUGIN_DIRS="$src/tests/outoftree/example_plugin" >"$work.log" 2>&1 ||
  { cat "$work.log"; echo "FAIL: granpipe does not configure with the example as an extra plugin folder"; exit 1; }
targets=$(ninja -C "$work" -t targets all)
for plugin in radius_stats contact_forces height_fit lattice; do
  grep -q "^granpipe_$plugin:" <<<"$targets" || { echo "FAIL: granpipe_$plugin is not in the build"; exit 1; }
done
! grep -q "^granpipe_packing:" <<<"$targets" || { echo "FAIL: packing is built but not selected"; exit 1; }
echo "the example's folder builds in granpipe's tree, whatever GRANPIPE_PLUGINS selects"
