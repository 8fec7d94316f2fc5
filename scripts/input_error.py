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
