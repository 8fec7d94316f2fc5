#!/usr/bin/env bash
# full_disk.sh GRANPIPE EXPECT WORKDIR
# Runs on a 64 KiB file system filled to several levels, so that the disk fills while
# the marker, pipeline.json, frames.h5 or results.h5 and the CSVs are written: exit 2 and
# one line (never a crash), no file of the failed run under its final name, and the
# directory marked failed. Needs a private tmpfs (root, unshare): skipped (77) otherwise.
set -eu
exe=$1 expect=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work/disk"
if [ -z "${GRANPIPE_IN_PRIVATE_MOUNT:-}" ]; then
  unshare -m true 2>/dev/null || { echo "skipped: cannot make a private mount namespace"; exit 77; }
  GRANPIPE_IN_PRIVATE_MOUNT=1 exec unshare -m "$0" "$@"
fi
disk=$work/disk
for free_kib in 0 4 8 16 24 32 48; do
  for save_frames in true false; do
    mount -t tmpfs -o size=64k tmpfs "$disk" || { echo "skipped: cannot mount a tmpfs"; exit 77; }
    head -c $(((64 - free_kib) * 1024)) /dev/zero >"$disk/filler" 2>/dev/null || true
    echo "-- $free_kib KiB free, save_frames $save_frames"
    said=$("$expect" 2 "^granpipe: $disk/run/.*(disk full|No space left on device|cannot (create|flush|write|close))" \
      -- "$exe" "$here/long_lattice.json" --quiet --set source.params.frames=4 \
         --set output.save_frames=$save_frames --out "$disk/run") || { echo "$said"; exit 1; }
    echo "$said"
    # A file that cannot be created says why, not what might be the reason.
    case "$said" in *"cannot create the file (does"*) echo "FAIL: no reason given"; exit 1 ;; esac
    for final in frames.h5 results.h5 packing.scalars.csv packing.profile.csv source.scalars.csv; do
      [ ! -e "$disk/run/$final" ] || { echo "FAIL: a failed run left $final"; exit 1; }
    done
    if [ -e "$disk/run" ]; then
      grep -q '"status":"failed"' "$disk/run/.granpipe-run" || { echo "FAIL: not marked failed"; exit 1; }
      # What the failed run left is listed as its own: with room again, --overwrite replaces it.
      mount -o remount,size=4m "$disk"
      "$exe" "$here/long_lattice.json" --quiet --no-report --set source.params.frames=2 \
        --set output.save_frames=false --out "$disk/run" --overwrite ||
        { echo "FAIL: --overwrite of the failed run refused"; ls -la "$disk/run"; exit 1; }
    fi
    umount "$disk"
  done
done

# An earlier run whose folder is a mount point cannot be swapped out: --overwrite was
# refused only at the end of the run, its results left aside. Refused before the run now.
mount -t tmpfs -o size=1m tmpfs "$disk" || { echo "skipped: cannot mount a tmpfs"; exit 77; }
"$exe" "$here/long_lattice.json" --quiet --no-report --set source.params.frames=2 --out "$disk"
"$expect" 2 "^granpipe: $disk: --overwrite would have to remove the earlier run in $disk but cannot \(it is a mount point, which cannot be renamed\); nothing was changed$" \
  -- "$exe" "$here/long_lattice.json" --quiet --no-report --set source.params.frames=2 --out "$disk" --overwrite
[ -z "$(ls -d "$disk".granpipe-* 2>/dev/null)" ] || { echo "FAIL: a refused run left a directory"; exit 1; }
umount "$disk"
# The same for a bind mount of the same file system (the same device as its parent).
mkdir -p "$work/bound"
mount --bind "$work/bound" "$work/bound" || { echo "skipped: cannot bind-mount"; exit 77; }
"$exe" "$here/long_lattice.json" --quiet --no-report --set source.params.frames=2 --out "$work/bound"
"$expect" 2 "^granpipe: $work/bound: --overwrite would have to remove the earlier run in $work/bound but cannot \(it is a mount point, which cannot be renamed\); nothing was changed$" \
  -- "$exe" "$here/long_lattice.json" --quiet --no-report --set source.params.frames=2 --out "$work/bound" --overwrite
umount "$work/bound"
echo "a full disk at every stage: one line, exit 2, no final-named file; a mount point not replaced"
