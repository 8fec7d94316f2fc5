"""granpipe --overwrite removes only what a run wrote into its folder, as listed in the
folder's .granpipe-manifest (core/src/run_manifest.hpp). A script that writes into a finished
run's folder (report.html, pooled tables beside the input) adds its file there, so that a
rerun replaces it with the run; any other file in the folder stops --overwrite."""
import os

MANIFEST = ".granpipe-manifest"


def note_written(path):
    """Adds `path`, a file just written, to the manifest of the folder holding it, when that
    folder is a granpipe run's."""
    folder, name = os.path.split(path)
    manifest = os.path.join(folder, MANIFEST)
    if os.path.islink(manifest) or not os.path.isfile(manifest):
        return
    with open(manifest) as f:
        if name in f.read().splitlines():
            return
    with open(manifest, "a") as f:
        f.write(name + "\n")
