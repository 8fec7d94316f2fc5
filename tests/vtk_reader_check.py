#!/usr/bin/python3
"""The vtk writer's sample files read by VTK's own XML reader (python3-vtk9): counts,
arrays and values of tests/vtk_sample_values.py. Exits 77 (skipped) without VTK.
Usage: vtk_reader_check.py DIR"""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

from vtk_sample_values import CELL_DATA, FILES, LINES, POINT_DATA, POINTS, same

try:
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:
    print("vtk_reader_check: skipped: VTK's Python module is absent (Debian: python3-vtk9)")
    sys.exit(77)


def check_arrays(where, data, expected):
    names = [data.GetArrayName(k) for k in range(data.GetNumberOfArrays())]
    if names != list(expected):
        sys.exit(f"{where}: expected arrays {list(expected)}, found {names}")
    for name, (_, components, numbers) in expected.items():
        array = data.GetArray(name)
        found = vtk_to_numpy(array).ravel().tolist()
        if array.GetNumberOfComponents() != components or not same(found, numbers):
            sys.exit(f"{where}/{name}: expected {components} components {numbers}, found "
                     f"{array.GetNumberOfComponents()} components {found}")


def check_polydata(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    if reader.GetErrorCode():
        sys.exit(f"{path}: VTK's reader failed")
    poly = reader.GetOutput()
    counts = (poly.GetNumberOfPoints(), poly.GetNumberOfVerts(), poly.GetNumberOfLines())
    if counts != (3, 3, 1):
        sys.exit(f"{path}: expected 3 points, 3 vertices and 1 line, found {counts}")
    check_arrays(f"{path}: point data", poly.GetPointData(), POINT_DATA)
    check_arrays(f"{path}: cell data", poly.GetCellData(), CELL_DATA)
    points = vtk_to_numpy(poly.GetPoints().GetData()).ravel().tolist()
    if points != POINTS:
        sys.exit(f"{path}: expected points {POINTS}, found {points}")
    line = poly.GetCell(3)  # vertices come first
    ends = [line.GetPointId(k) for k in range(line.GetNumberOfPoints())]
    if ends != LINES:
        sys.exit(f"{path}: expected the line {LINES}, found {ends}")


def main():
    directory = Path(sys.argv[1])
    listed = [d.get("file") for d in ET.parse(directory / "test.pvd").getroot().iter("DataSet")]
    if listed != FILES:
        sys.exit(f"test.pvd: expected {FILES}, found {listed}")
    for file in FILES:
        check_polydata(directory / file)
    print(f"vtk_reader_check: VTK reads {len(FILES)} frames as written")


if __name__ == "__main__":
    main()
