"""Another tool's H5MD run in two parts (continued_in), walls of edge 10 along every axis.
The first part's frames fit walls at [0, 10] and at [-5, 5], the second part's last frame
[-5, 5] only: each part placed its own walls, the base jumped by 5 between the parts (exit
0), then the genuine continuation was refused; the parts are placed alike, at [-5, 5]. Where
no placement holds every part's frames (the first part's first frame fits [0, 10] only), the
parts are refused, naming why. Frame 0 of a file decides an axis it fits one way only: a
grain escaped in a later frame does not move the walls of frame 0."""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np
from foreign_h5md import write_h5md

granpipe = sys.argv[1]


def plain_h5md(path, positions, first_step=0):
    """Frames of positions [T][N][3] in a walled box of edge 10."""
    write_h5md(path, np.asarray(positions, dtype=float), [10.0] * 3, "none", "othermd",
               first_step=first_step)


def run(work, name, params):
    pipeline = os.path.join(work, name + ".json")
    with open(pipeline, "w") as f:
        f.write('{"name": "%s", "source": {"plugin": "h5md", "params": %s}, '
                '"output": {"save_frames": true}}' % (name, params))
    return subprocess.run([granpipe, pipeline, "--quiet", "--no-report", "--out", os.path.join(work, name)],
                          capture_output=True, text=True)


with tempfile.TemporaryDirectory() as work:
    two = [[1.0, 1.0, 1.0], [3.0, 3.0, 3.0]]
    first, second = os.path.join(work, "q1.h5"), os.path.join(work, "q2.h5")
    plain_h5md(first, [two, two])
    plain_h5md(second, [two, [[1.0, 1.0, -0.5], [3.0, 3.0, 3.0]]], first_step=1)
    r = run(work, "parts", '{"file": "%s", "continued_in": ["%s"]}' % (first, second))
    assert r.returncode == 0, (r.returncode, r.stderr)
    with h5py.File(os.path.join(work, "parts", "frames.h5"), "r") as f:
        lo = f["granpipe/container/lo"][()]
    assert (lo[:, 2] == -5.0).all(), lo

    apart = os.path.join(work, "q0.h5")
    plain_h5md(apart, [[[1.0, 1.0, 7.0], [3.0, 3.0, 3.0]], two])
    r = run(work, "apart", '{"file": "%s", "continued_in": ["%s"]}' % (apart, second))
    assert r.returncode == 2, (r.returncode, r.stderr)
    expected = ("got another container than " + apart + ": frame 1 (extent along z -5 to 5, there 0 to 10; "
                "H5MD stores no origin, and no place of the walls holds every part's frames; not a continuation of it)")
    assert expected in r.stderr, r.stderr

    # x placed alike (centred: the first part's first frame), z placed apart: the refusal
    # names z, the axis where no placement holds every part's frames.
    mixed = os.path.join(work, "q3.h5")
    plain_h5md(mixed, [[[-1.0, 1.0, 7.0], [1.0, 3.0, 3.0]], two])
    r = run(work, "mixed", '{"file": "%s", "continued_in": ["%s"]}' % (mixed, second))
    assert r.returncode == 2 and "(extent along z -5 to 5, there 0 to 10;" in r.stderr, r.stderr

    escaped = os.path.join(work, "escaped.h5")
    plain_h5md(escaped, [[[-1.0, 1.0, 1.0], [1.0, 3.0, 3.0]], [[100.0, 1.0, 1.0], [1.0, 3.0, 3.0]]])
    r = run(work, "escaped", '{"file": "%s", "last": 0}' % escaped)
    assert r.returncode == 0, (r.returncode, r.stderr)
print("another tool's parts placed alike, or refused where no placement holds them; frame 0 decides its axes")
