"""report.html's picture of a run's last saved frame: 2D disks with their arches, a 3D
packing's side view, the contact network drawn with line widths in proportion to the force."""
import html
import io
import os

from report_h5 import (HDF5_ERRORS, Damaged, damaged, member, not_a_file, numbers_dataset,
                       unreadable, within_reach)

MAX_DRAWN_PARTICLES = 20000  # a configuration picture of more would be pages of SVG


def open_frames(path):
    """The frames file, open to read (a run still writing it may go on: SWMR)."""
    import h5py
    what = not_a_file(path)  # h5py would wait on a FIFO for ever
    if what:
        raise Damaged(f"{path}: expected a granpipe frames file, found {what}")
    try:
        return h5py.File(path, "r", swmr=True)
    except OSError as e:  # not HDF5, or cut short: said as report.py says it of results.h5
        raise Damaged(f"{path}: expected a granpipe frames file, found one HDF5 cannot open: "
                      f"{e}") from None


def frame_rows(particles, name, t, n=None):
    """Frame t of particles/all/<name>/value: a row per particle (n of them when given);
    a position or radius not finite (or a radius below 0) is damage: granpipe saves none."""
    import numpy as np
    ds = numbers_dataset(particles, f"{name}/value", 3 if name == "position" else 2)
    if ds.shape[0] <= t:
        raise damaged(ds, f"{t + 1} frames (as many as position/step)", ds.shape[0])
    if n is not None and ds.shape[1] != n:
        raise damaged(ds, f"{n} particles (as many as position)", ds.shape[1])
    if name == "position" and ds.shape[2] not in (2, 3):
        raise damaged(ds, "2 or 3 coordinates", ds.shape[2])
    within_reach(ds, ds.size // max(ds.shape[0], 1))
    rows = ds[t]
    if name in ("position", "radius"):
        bad = ~np.isfinite(rows) | ((rows < 0) if name == "radius" else False)
        if bad.any():
            expected = "finite numbers >= 0" if name == "radius" else "finite numbers"
            raise damaged(ds, f"{expected} in frame {t}", rows[np.unravel_index(
                np.argmax(bad), bad.shape)])
    return rows


def last_frame(path):
    """(positions, radii, particle columns {"arch": values} where saved, contacts (i, j, |F_n|)
    or None, step) of the last frame of a granpipe frames file."""
    with open_frames(path) as f:
        particles = member(f, "particles/all", "group")
        steps = numbers_dataset(particles, "position/step", 1)
        t = len(steps) - 1
        if t < 0:
            return None
        x = frame_rows(particles, "position", t)
        columns = {"arch": frame_rows(particles, "arch", t, len(x))} if "arch" in particles else {}
        return (x, frame_rows(particles, "radius", t, len(x)), columns,
                last_contacts(f, t, len(x)), int(steps[t]))


def last_contacts(f, t, n):
    """(i, j, |F_n|) of the contacts of frame t among n particles (j < 0: a wall), or None
    when the file has no contact forces."""
    import numpy as np
    if "granpipe/contacts" not in f:
        return None
    c = member(f, "granpipe/contacts", "group")
    if "normal_force" not in c:
        return None
    offset, count = (numbers_dataset(c, k, 1, integer=True) for k in ("offset", "count"))
    for ds in (offset, count):
        if len(ds) <= t:
            raise damaged(ds, f"{t + 1} frames (as many as position/step)", len(ds))
    rows = slice(int(offset[t]), int(offset[t] + count[t]))
    i, j = (numbers_dataset(c, k, 1, integer=True) for k in ("i", "j"))
    force = numbers_dataset(c, "normal_force", 2)
    for ds in (i, j, force):
        if not 0 <= rows.start <= rows.stop <= len(ds):
            raise damaged(ds, f"rows {rows.start} to {rows.stop} (offset and count of frame {t})",
                          f"{len(ds)} rows")
    within_reach(force, 3 * (rows.stop - rows.start))
    first, second = i[rows], j[rows]
    for ds, values, bad in ((i, first, (first < 0) | (first >= n)),
                            (j, second, second >= n)):  # j < 0: a wall
        if bad.any():
            raise damaged(ds, f"particle indices below {n}", values[np.argmax(bad)])
    return first, second, np.linalg.norm(force[rows], axis=-1)


def configuration_svg(plt, frame):
    """The last frame drawn: 2D disks (an arch's disks coloured by arch), or a 3D packing's
    side view (x, z) of the slab of centres within a mean radius of the middle y, each sphere
    as its section by the mid-plane; particle-particle contacts in view as lines of width in
    proportion to |F_n| (the BNP paper's Fig. 11)."""
    import numpy as np
    from matplotlib.collections import LineCollection, PatchCollection
    from matplotlib.patches import Circle
    x, r, columns, contacts, step = frame
    if x.shape[1] == 3:
        # The slab through the centre nearest the middle: between two layers of a crystal
        # the middle itself held no centre, and the view was empty.
        halfway = 0.5 * (x[:, 1].min() + x[:, 1].max())
        middle = x[np.argmin(np.abs(x[:, 1] - halfway)), 1]
        depth = x[:, 1] - middle
        shown = np.abs(depth) < r.mean()
        section = np.sqrt(np.maximum(r**2 - depth**2, 0.0))
        xy, size, title = x[:, [0, 2]], section, f"side view of the slab |y - {middle:.3g}| < R̄"
    else:
        shown, xy, size, title = np.ones(len(r), bool), x, r, "the packing"
    if shown.sum() > MAX_DRAWN_PARTICLES:
        return None
    arch = columns.get("arch")
    colours = ["#c8c8c8" if arch is None or a < 0 else plt.cm.tab20(int(a) % 20)
               for a in (arch if arch is not None else np.full(len(r), -1))]
    index = np.flatnonzero(shown)
    extent = np.ptp(xy[index], axis=0) + 2.0 * r.max()
    tall = float(np.clip(extent[1] / extent[0], 0.5, 2.0))  # a tall bed drawn tall, within reason
    fig, ax = plt.subplots(figsize=(6.4, 6.4 * tall))
    ax.add_collection(PatchCollection([Circle(xy[k], size[k]) for k in index],
                                      facecolors=[colours[k] for k in index], edgecolors="k",
                                      linewidths=0.2))
    if contacts is not None:
        i, j, force = contacts
        keep = (j >= 0) & (force > 0)
        keep[keep] &= shown[i[keep]] & shown[j[keep]]
        if keep.any():
            segments = np.stack([xy[i[keep]], xy[j[keep]]], axis=1)
            ax.add_collection(LineCollection(segments, colors="#b22",
                                             linewidths=3.0 * force[keep] / force[keep].max()))
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_title(f"{title}, step {step}")
    ax.set_xlabel("x")
    ax.set_ylabel("z" if x.shape[1] == 3 else "y")
    fig.tight_layout()
    out = io.StringIO()
    fig.savefig(out, format="svg", metadata={"Date": None})
    plt.close(fig)
    svg = out.getvalue()
    return svg[svg.index("<svg"):]


def configuration_section(plt, run):
    """A picture of the last saved frame, when the run saved frames (a sweep: its first point)."""
    for name in ("frames.h5", "frames.partial.h5", "point_000/frames.h5",
                 "point_000/frames.partial.h5"):
        path = os.path.join(run, name)
        if os.path.exists(path):
            break
    else:
        return ""
    if plt is None:
        return ""
    try:
        frame = last_frame(path)
    except HDF5_ERRORS as e:  # an object HDF5 cannot read (a flipped byte)
        raise unreadable(path, e, "frames") from None
    if frame is not None and len(frame[0]) == 0:
        return (f"<p class=note>{html.escape(name)}: no picture (its last frame has no "
                "particle)</p>")
    svg = configuration_svg(plt, frame) if frame is not None else None
    if svg is None:
        return (f"<p class=note>{html.escape(name)}: no picture (no frame, or more than "
                f"{MAX_DRAWN_PARTICLES} particles in view)</p>")
    return (f"<h2>Configuration</h2><figure id=configuration>{svg}<figcaption>the last frame of "
            f"{html.escape(name)}</figcaption></figure>")
