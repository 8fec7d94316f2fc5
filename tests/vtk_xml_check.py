#!/usr/bin/python3
"""The vtk writer's sample files (written by write_vtk_samples) read back with Python's own
XML parser: the .pvd lists both frames with their times, each .vtp has the counts, arrays,
types, components and values of tests/vtk_sample_values.py. Usage: vtk_xml_check.py DIR"""
import base64
import struct
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

from vtk_sample_values import CELL_DATA, FILES, LINES, POINT_DATA, POINTS, TIMESTEPS, same

FORMATS = {"Float64": "d", "Int64": "q", "Int32": "i"}


def values(array):
    """The numbers of a DataArray, ASCII or base64 "binary" after a UInt64 byte count."""
    if array.get("format") == "ascii":
        return [int(v) for v in array.text.split()] if array.text else []
    data = base64.b64decode(array.text)
    (size,) = struct.unpack_from("<Q", data)
    if size != len(data) - 8:
        sys.exit(f"{array.get('Name')}: header says {size} bytes, found {len(data) - 8}")
    count = size // struct.calcsize(FORMATS[array.get("type")])
    return list(struct.unpack_from(f"<{count}{FORMATS[array.get('type')]}", data, 8))


def check_arrays(where, element, expected):
    arrays = element.findall("DataArray")
    names = [a.get("Name") for a in arrays]
    if names != list(expected):
        sys.exit(f"{where}: expected arrays {list(expected)}, found {names}")
    for a in arrays:
        vtk_type, components, numbers = expected[a.get("Name")]
        found = (a.get("type"), int(a.get("NumberOfComponents")), values(a))
        if found[:2] != (vtk_type, components) or not same(found[2], numbers):
            sys.exit(f"{where}/{a.get('Name')}: expected {(vtk_type, components, numbers)}, "
                     f"found {found}")


def check_polydata(path):
    piece = ET.parse(path).getroot().find("PolyData/Piece")
    counts = {k: piece.get(k) for k in ("NumberOfPoints", "NumberOfVerts", "NumberOfLines")}
    if counts != {"NumberOfPoints": "3", "NumberOfVerts": "3", "NumberOfLines": "1"}:
        sys.exit(f"{path}: counts {counts}")
    check_arrays(f"{path}: PointData", piece.find("PointData"), POINT_DATA)
    check_arrays(f"{path}: CellData", piece.find("CellData"), CELL_DATA)
    check_arrays(f"{path}: Points", piece.find("Points"),
                 {"position": ("Float64", 3, POINTS)})
    lines = {a.get("Name"): values(a) for a in piece.findall("Lines/DataArray")}
    verts = {a.get("Name"): values(a) for a in piece.findall("Verts/DataArray")}
    if lines != {"connectivity": LINES, "offsets": [2]}:
        sys.exit(f"{path}: lines {lines}")
    if verts != {"connectivity": [0, 1, 2], "offsets": [1, 2, 3]}:
        sys.exit(f"{path}: vertices {verts}")


def main():
    directory = Path(sys.argv[1])
    datasets = ET.parse(directory / "test.pvd").getroot().findall("Collection/DataSet")
    found = [(d.get("file"), float(d.get("timestep"))) for d in datasets]
    if found != list(zip(FILES, TIMESTEPS)):
        sys.exit(f"test.pvd: expected {list(zip(FILES, TIMESTEPS))}, found {found}")
    for file in FILES:
        check_polydata(directory / file)
    print(f"vtk_xml_check: {len(FILES)} frames as written")


if __name__ == "__main__":
    main()
