#!/usr/bin/env bash
# build_info_dirty.sh BUILD_INFO_CMAKE WORKDIR
# The commit a build names is "-dirty" when the tree holds a file git does not track (the
# build compiles every core/src/*.cpp and plugin folder, tracked or not): an untracked
# new_plugin.cpp left it clean.
set -eu
script=$1 work=$2
rm -rf "$work" && mkdir -p "$work/repo"
cd "$work/repo"
git init -q . && git -c user.name=t -c user.email=t@t commit -q --allow-empty -m start
commit_of() {
  cmake -DSOURCE_DIR="$work/repo" -DOUTPUT="$work/info.cpp" -DVERSION=0 -P "$script"
  sed -n 's/.*git_commit() { return "\(.*\)"; }.*/\1/p' "$work/info.cpp"
}
clean=$(commit_of)
case "$clean" in *-dirty) echo "FAIL: a clean tree named $clean"; exit 1 ;; esac
echo "int new_plugin;" > new_plugin.cpp
dirty=$(commit_of)
[ "$dirty" = "$clean-dirty" ] || { echo "FAIL: an untracked source named $dirty, expected $clean-dirty"; exit 1; }
echo "an untracked source makes the build's commit $dirty"
