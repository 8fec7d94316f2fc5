#!/usr/bin/env bash
# overwrite_permissions.sh GRANPIPE EXPECT PIPELINE WORKDIR
# --overwrite of an earlier run that this user may not remove (a read-only folder in it,
# or a read-only parent) is refused before anything changes: the earlier run stays whole.
# Run as an ordinary user; as root (whom permissions do not stop) the runs are made as
# "nobody" through setpriv, and the test is skipped (77) when that is not possible.
set -eu
exe=$1 expect=$2 pipeline=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
as_user=()
if [ "$(id -u)" -eq 0 ]; then
  command -v setpriv >/dev/null || { echo "skipped: root without setpriv"; exit 77; }
  as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups --)
  chown 65534:65534 "$work"
  "${as_user[@]}" test -x "$exe" -a -r "$pipeline" || { echo "skipped: nobody cannot reach the build"; exit 77; }
fi
run() { "${as_user[@]}" "$@"; }
sum() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 md5sum); }

run "$exe" "$pipeline" --quiet --out "$work/parent/earlier"
sum "$work/parent/earlier" >"$work/earlier.sum"

# A folder of the earlier run that its owner made read-only.
run chmod a-w "$work/parent/earlier/point_003"
"$expect" 2 "point_003: --overwrite would have to remove the earlier run in $work/parent/earlier but cannot \(Permission denied\); nothing was changed" \
  -- "${as_user[@]}" "$exe" "$pipeline" --quiet --out "$work/parent/earlier" --overwrite
run chmod u+w "$work/parent/earlier/point_003"

# A parent where the new run cannot be built.
run chmod a-w "$work/parent"
"$expect" 2 "parent: --overwrite would have to remove the earlier run in $work/parent/earlier but cannot \(Permission denied\)" \
  -- "${as_user[@]}" "$exe" "$pipeline" --quiet --out "$work/parent/earlier" --overwrite
run chmod u+w "$work/parent"

# In a sticky folder (as /tmp) another user's earlier run cannot be renamed by this one,
# writable as it is: refused at the end of the run before, its results left aside.
if [ "$(id -u)" -eq 0 ]; then
  mkdir -m 1777 "$work/sticky"
  "$exe" "$pipeline" --quiet --no-report --out "$work/sticky/earlier"
  chmod -R a+rwX "$work/sticky/earlier"
  "$expect" 2 "earlier: --overwrite would have to remove the earlier run in $work/sticky/earlier but cannot \(another user owns it, in a folder where only owners may rename\); nothing was changed" \
    -- "${as_user[@]}" "$exe" "$pipeline" --quiet --out "$work/sticky/earlier" --overwrite
fi

sum "$work/parent/earlier" | cmp -s - "$work/earlier.sum" || { echo "FAIL: a refused --overwrite changed the earlier run"; exit 1; }
[ -z "$(ls -d "$work"/parent/earlier.granpipe-* 2>/dev/null)" ] || { echo "FAIL: a refused run left a directory"; exit 1; }
echo "--overwrite refused before changing anything it could not finish"
