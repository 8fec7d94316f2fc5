#!/usr/bin/env python3
"""Fails when a tracked file names an absolute path of a build machine.

Docs, defaults and data provenance name files relative to the project root
(`../shared/...`); a path from one machine's home or checkout means nothing on another
machine and leaks the one it came from. HDF5 samples are scanned too: their provenance
attribute holds the pipeline that made them, file parameters included.

    check_no_absolute_paths.py SOURCE_DIR
"""
import os
import re
import subprocess
import sys

# Roots under which a development or CI machine keeps checkouts, homes and scratch runs;
# a path is only flagged where one starts (after a quote, a space, '=', '(' or a line's
# start), so "$work/home/me" in a test script, a variable's subfolder, is not.
MACHINE_ROOTS = ("work", "home", "root", "Users", "tmp/tmp", "mnt", "scratch")
BOUNDARY = r"(?:^|(?<=[\s\"'`=(:,\[]))"


def tracked_files(source_dir):
    try:
        out = subprocess.run(["git", "-C", source_dir, "ls-files", "-z"], check=True,
                             capture_output=True).stdout
        return [name for name in out.decode().split("\0") if name]
    except (OSError, subprocess.CalledProcessError):
        # A source tree without git (an unpacked archive): every file but build output.
        skipped = {".git", "build", "out"}
        found = []
        for folder, subfolders, names in os.walk(source_dir):
            subfolders[:] = [s for s in subfolders if s not in skipped]
            found += [os.path.relpath(os.path.join(folder, n), source_dir) for n in names]
        return found


def machine_path_pattern(source_dir):
    roots = [re.escape("/" + r + "/") for r in MACHINE_ROOTS]
    # The checkout's own location, wherever it is, and the folder that holds it.
    here = os.path.realpath(source_dir)
    roots += [re.escape(here), re.escape(os.path.dirname(here) + "/")]
    return re.compile((BOUNDARY + "(" + "|".join(roots) + ")").encode(), re.MULTILINE)


def main():
    source_dir = sys.argv[1]
    pattern = machine_path_pattern(source_dir)
    bad = []
    for name in tracked_files(source_dir):
        path = os.path.join(source_dir, name)
        if not os.path.isfile(path):
            continue
        with open(path, "rb") as f:
            data = f.read()
        for match in pattern.finditer(data):
            line = data.count(b"\n", 0, match.start()) + 1
            end = data.find(b"\n", match.start())
            found = data[match.start():end if end != -1 else None][:80].decode(errors="replace")
            bad.append(f"{name}:{line}: expected paths relative to the project root, found {found}")
    for line in bad:
        print(line)
    print(f"absolute paths: {len(bad)} found in tracked files")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
