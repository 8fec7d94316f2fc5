"""Bad input ends a script as it ends granpipe: one line on stderr naming the file, what was
expected and what was found, and exit code 2 (1 is left for the scripts' own failures)."""

import json
import os
import sys


def refuse(message):
    """Prints `message`, one line, and exits with code 2."""
    print(message, file=sys.stderr)
    sys.exit(2)


def read_pipeline(out_dir):
    """The resolved pipeline.json a granpipe run wrote into `out_dir`."""
    path = os.path.join(out_dir, "pipeline.json")
    try:
        with open(path) as f:
            return json.load(f)
    except OSError as e:
        refuse(f"{path}: expected the pipeline of a granpipe run, found none: {e.strerror}")
    except ValueError as e:
        refuse(f"{path}: expected the pipeline of a granpipe run, found no JSON: {e}")


def labelled_run(argument):
    """(run directory, its pipeline, its label) of a RUN_DIR[=LABEL] argument: the LABEL
    given, else "ε = <epsilon>" from the pipeline's source, else the pipeline's name."""
    run, _, label = argument.partition("=")
    pipeline = read_pipeline(run)
    if not label:
        eps = pipeline.get("source", {}).get("params", {}).get("epsilon")
        label = f"ε = {eps:g}" if eps is not None else pipeline.get("name", run)
    return run, pipeline, label


def _folder_holding(path, folders):
    """The first of `folders` that `path` lies inside, or None."""
    real = os.path.realpath(path)
    for folder in folders:
        top = os.path.realpath(folder)
        if os.path.commonpath([top, real]) == top:
            return folder
    return None


def require_outputs(outputs, read=(), runs=()):
    """Refuses, before anything is written, an output whose folder does not exist, one that is a
    file the script reads (`read`), or an existing file inside a run folder it reads (`runs`):
    a script's results never replace the tables and frames they were computed from."""
    files_read = {os.path.realpath(p): p for p in read}
    for out in outputs:
        folder = os.path.dirname(out) or "."
        if not os.path.isdir(folder):
            refuse(f"{out}: expected an output in an existing folder, got no folder {folder}")
        if os.path.realpath(out) in files_read:
            refuse(f"{out}: expected an output apart from the files read, got the input "
                   f"{files_read[os.path.realpath(out)]}")
        run = _folder_holding(out, runs)
        if run is not None and os.path.lexists(out):
            refuse(f"{out}: expected an output outside the run folders read ({', '.join(runs)}), "
                   f"got a file in {run}")


def output_prefix(prefix, suffixes, read=(), runs=()):
    """The outputs OUT_PREFIX + each suffix, checked by require_outputs; a prefix that is a
    folder is refused (a run folder given where OUT_PREFIX, the last argument, was forgotten)."""
    if os.path.isdir(prefix):
        refuse(f"{prefix}: expected OUT_PREFIX (the last argument), the start of the outputs' "
               "path, got a folder")
    outputs = [prefix + s for s in suffixes]
    require_outputs(outputs, read, runs)
    return outputs
