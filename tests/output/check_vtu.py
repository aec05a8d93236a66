#!/usr/bin/env python3
"""Reads .vtu / .pvd files with VTK's own XML readers and prints what it read, one fact a line,
for tests/output/vtk_writer_test.cpp to check:

  points N / cells M / point I X Y Z / cell I TYPE NODE...
  point_array NAME COMPONENTS TUPLES / cell_array NAME COMPONENTS TUPLES
  point_value NAME TUPLE COMPONENT VALUE / cell_value NAME TUPLE COMPONENT VALUE
  dataset TIME PART FILE   (for a .pvd, parsed as XML: Debian's VTK has no .pvd reader, that
                            one is ParaView's; then the lines of that file's .vtu)

Numbers are printed with repr(), which round-trips a double exactly.
Exits non-zero if a reader reports an error.
"""
import os
import sys
import xml.etree.ElementTree as ET

from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


class ErrorFlag:
    def __init__(self):
        self.messages = []

    def __call__(self, caller, event):
        self.messages.append(event)


def read_vtu(path):
    reader = vtkXMLUnstructuredGridReader()
    flag = ErrorFlag()
    reader.AddObserver("ErrorEvent", flag)
    reader.SetFileName(path)
    reader.Update()
    if flag.messages or reader.GetErrorCode() != 0:
        sys.exit(f"VTK reader failed on {path}")
    grid = reader.GetOutput()
    print("points", grid.GetNumberOfPoints())
    print("cells", grid.GetNumberOfCells())
    for i in range(grid.GetNumberOfPoints()):
        print("point", i, *map(repr, grid.GetPoint(i)))
    for i in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(i).GetPointIds()
        nodes = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        print("cell", i, grid.GetCellType(i), *nodes)
    for kind, data in (("point", grid.GetPointData()), ("cell", grid.GetCellData())):
        for a in range(data.GetNumberOfArrays()):
            array = data.GetArray(a)
            name = array.GetName()
            comps = array.GetNumberOfComponents()
            print(f"{kind}_array", name, comps, array.GetNumberOfTuples())
            for t in range(array.GetNumberOfTuples()):
                for c in range(comps):
                    print(f"{kind}_value", name, t, c, repr(array.GetComponent(t, c)))


def read_pvd(path):
    root = ET.parse(path).getroot()
    if root.get("type") != "Collection":
        sys.exit(f"{path} is not a VTK collection")
    folder = os.path.dirname(path)
    for dataset in root.iter("DataSet"):
        print("dataset", repr(float(dataset.get("timestep"))), dataset.get("part"),
              dataset.get("file"))
        read_vtu(os.path.join(folder, dataset.get("file")))


def main():
    for path in sys.argv[1:]:
        if path.endswith(".pvd"):
            read_pvd(path)
        else:
            read_vtu(path)


if __name__ == "__main__":
    main()
