"""report.html's picture of a run's last saved frame: 2D disks with their arches, a 3D
packing's side view, the contact network drawn with line widths in proportion to the force."""
import html
import io
import os

MAX_DRAWN_PARTICLES = 20000  # a configuration picture of more would be pages of SVG


def last_frame(path):
    """(positions, radii, particle columns {name: values}, contacts (i, j, |F_n|) or None,
    step) of the last frame of a granpipe frames file."""
    import h5py
    import numpy as np
    with h5py.File(path, "r", swmr=True) as f:
        particles = f["particles/all"]
        t = len(particles["position/step"]) - 1
        if t < 0:
            return None
        columns = {name: particles[name]["value"][t] for name in particles
                   if name not in ("position", "radius", "box") and "value" in particles[name]}
        contacts = None
        if "granpipe/contacts" in f and "normal_force" in f["granpipe/contacts"]:
            c = f["granpipe/contacts"]
            rows = slice(int(c["offset"][t]), int(c["offset"][t] + c["count"][t]))
            force = np.linalg.norm(np.atleast_2d(c["normal_force"][rows]), axis=-1)
            contacts = (c["i"][rows], c["j"][rows], force)
        return (particles["position/value"][t], particles["radius/value"][t], columns, contacts,
                int(particles["position/step"][t]))


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
    for name in ("frames.h5", "frames.partial.h5", "point_000/frames.h5"):
        path = os.path.join(run, name)
        if os.path.exists(path):
            break
    else:
        return ""
    if plt is None:
        return ""
    frame = last_frame(path)
    svg = configuration_svg(plt, frame) if frame is not None else None
    if svg is None:
        return (f"<p class=note>{html.escape(name)}: no picture (no frame, or more than "
                f"{MAX_DRAWN_PARTICLES} particles in view)</p>")
    return (f"<h2>Configuration</h2><figure id=configuration>{svg}<figcaption>the last frame of "
            f"{html.escape(name)}</figcaption></figure>")
