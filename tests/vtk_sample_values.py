"""What tests/plugins/vtk_sample_frames.hpp holds, as the .vtp files must hold it: point
data, cell data (three vertex cells of "no value" first, then the one line) and points."""
import math

NAN = math.nan

POINT_DATA = {  # name: (VTK type, components, values)
    "radius": ("Float64", 1, [0.5, 0.5, 0.25]),
    "id": ("Int64", 1, [10, 11, 12]),
    "species": ("Int32", 1, [0, 0, 1]),
    "velocity": ("Float64", 3, [1, 2, 3, 0, 0, -1, 0.5, 0, 0]),
    "network": ("Int64", 1, [0, 0, -1]),
    "voronoi_volume": ("Float64", 1, [1.5, 2.5, NAN]),
}
CELL_DATA = {
    "overlap": ("Float64", 1, [NAN] * 3 + [0.125]),
    "normal_force": ("Float64", 3, [NAN] * 9 + [-2, 0, 0]),
    "mst_pass": ("Int64", 1, [-1, -1, -1, 1]),
}
POINTS = [0, 0, 0, 1, 0, 0, 0.5, 1, 0.25]
LINES = [0, 1]
FILES = ["test_000000.vtp", "test_000001.vtp"]
TIMESTEPS = [0.5, 0.75]


def same(found, expected):
    """Exact equality, NaN equal to NaN."""
    return len(found) == len(expected) and all(
        (math.isnan(e) and math.isnan(f)) if isinstance(e, float) and math.isnan(e) else f == e
        for f, e in zip(found, expected))
