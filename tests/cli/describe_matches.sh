#!/usr/bin/env bash
# describe_matches.sh GRANPIPE PLUGIN EXPECTED: `granpipe describe PLUGIN` prints EXPECTED
# (but for the library's path, which depends on the build).
set -u
exe=$1 plugin=$2 expected=$3
diff <("$exe" describe "$plugin" | grep -v '^library: ') "$expected" && echo "ok: describe $plugin"
