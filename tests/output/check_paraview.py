"""Opens a run folder's ParaView series with ParaView's own reader, under pvbatch:

    pvbatch tests/output/check_paraview.py RUN_FOLDER HEAD RHO_G

(paraview.simple.OpenDataFile picks PVDReader for a .pvd, which reads each .vtu with VTK's XML
reader). For the run of scenarios/verification/coupled_hydrostatic_column.toml, still water at
head HEAD with the hydrostatic pressure p = RHO_G (h - z), it checks:
  - fluid.pvd, blocks.pvd, contacts.pvd and fractures.pvd list the same coupling iterations, increasing, the
    last being summary.json's;
  - every array the docs name is there, one tuple per point or cell, vectors with 3 components;
  - at the last time, every head is HEAD and every pressure RHO_G (h - z) (to 1e-9 of RHO_G HEAD),
    and each block's id, area, rotation and displacement are summary.json's, exactly;
  - aperture = max(0, -penetration) for every contact, and block_i, block_j name blocks;
  - fractures.pvd: the two fractures' lines, 1 m each, no aperture where closed.
Prints one fact a line; exits 1 with a message at the first mismatch.
"""
import json
import os
import sys

from paraview import servermanager
from paraview.simple import OpenDataFile


def fail(message):
    print("FAIL", message)
    sys.exit(1)


def expect(condition, message):
    if not condition:
        fail(message)


def open_series(folder, name, iterations, times_seen):
    path = os.path.join(folder, name + ".pvd")
    reader = OpenDataFile(path)
    expect(reader is not None, f"ParaView cannot open {path}")
    expect(reader.GetXMLName() == "PVDReader", f"{path} opened by {reader.GetXMLName()}")
    times = list(reader.TimestepValues)
    expect(times and times == sorted(set(times)) and times[-1] == iterations,
           f"{name}.pvd times {times}: not increasing to the last iteration {iterations}")
    times_seen.setdefault("times", times)
    expect(times == times_seen["times"], f"{name}.pvd times {times}, fluid.pvd's {times_seen['times']}")
    reader.UpdatePipeline(times[-1])
    grid = servermanager.Fetch(reader)
    print(name, "times", len(times), "points", grid.GetNumberOfPoints(), "cells",
          grid.GetNumberOfCells())
    expect(grid.GetNumberOfCells() > 0, f"{name}: no cells")
    return grid


def arrays(grid, kind, expected):
    """The named arrays of the point or cell data, each checked for its size."""
    data = grid.GetPointData() if kind == "point" else grid.GetCellData()
    count = grid.GetNumberOfPoints() if kind == "point" else grid.GetNumberOfCells()
    names = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays())]
    expect(names == list(expected), f"{kind} arrays {names}, expected {list(expected)}")
    found = {}
    for name, components in expected.items():
        array = data.GetArray(name)
        expect(array.GetNumberOfComponents() == components,
               f"{name}: {array.GetNumberOfComponents()} components, expected {components}")
        expect(array.GetNumberOfTuples() == count,
               f"{name}: {array.GetNumberOfTuples()} tuples, expected {count}")
        found[name] = array
    print(kind, "arrays", *names)
    return found


def main():
    folder, head, rho_g = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    iterations = summary["iterations"]
    times_seen = {}

    fluid = open_series(folder, "fluid", iterations, times_seen)
    point = arrays(fluid, "point", {"head": 1, "pressure": 1})
    arrays(fluid, "cell", {"permeability": 1, "porosity": 1, "flux": 3, "region": 1})
    for i in range(fluid.GetNumberOfPoints()):
        h, p, z = point["head"].GetValue(i), point["pressure"].GetValue(i), fluid.GetPoint(i)[1]
        expect(abs(h - head) <= 1e-9 * head, f"head {h} at point {i}, expected {head}")
        expect(abs(p - rho_g * (h - z)) <= 1e-9 * rho_g * head,
               f"pressure {p} at point {i}, expected {rho_g * (h - z)}")
    print("heads and hydrostatic pressures as given")

    blocks = open_series(folder, "blocks", iterations, times_seen)
    cell = arrays(blocks, "cell",
                  {"block": 1, "displacement": 3, "rotation": 1, "stress": 3, "area": 1})
    expect(blocks.GetNumberOfCells() == len(summary["blocks"]),
           f"{blocks.GetNumberOfCells()} blocks, summary.json has {len(summary['blocks'])}")
    for b, block in enumerate(summary["blocks"]):
        expect(cell["block"].GetValue(b) == block["id"], f"block {b} has id {cell['block'].GetValue(b)}")
        expect(cell["area"].GetValue(b) == block["area"], f"block {b} area")
        expect(cell["rotation"].GetValue(b) == block["rotation"], f"block {b} rotation")
        u = cell["displacement"].GetTuple3(b)
        expect(list(u) == block["displacement"] + [0.0], f"block {b} displacement {u}")
    print("blocks as summary.json")

    contacts = open_series(folder, "contacts", iterations, times_seen)
    cell = arrays(contacts, "cell", {"state": 1, "normal_force": 1, "penetration": 1, "aperture": 1,
                                     "block_i": 1, "block_j": 1})
    for c in range(contacts.GetNumberOfCells()):
        expect(cell["aperture"].GetValue(c) == max(0.0, -cell["penetration"].GetValue(c)),
               f"contact {c} aperture")
        for side in ("block_i", "block_j"):
            expect(0 <= cell[side].GetValue(c) < len(summary["blocks"]), f"contact {c} {side}")
    print("contacts consistent")

    # The column is cut by two 1 m fractures (ids 0 and 1): their lines add up to 1 m each (the
    # blocks strain by ~1e-7), and a closed piece has no aperture.
    fractures = open_series(folder, "fractures", iterations, times_seen)
    cell = arrays(fractures, "cell",
                  {"fracture": 1, "aperture": 1, "shear": 1, "open": 1, "hydraulic_aperture": 1, "flow": 1})
    lengths = {}
    for c in range(fractures.GetNumberOfCells()):
        ids = fractures.GetCell(c).GetPointIds()
        a, b = fractures.GetPoint(ids.GetId(0)), fractures.GetPoint(ids.GetId(1))
        f = int(cell["fracture"].GetValue(c))
        lengths[f] = lengths.get(f, 0.0) + ((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2) ** 0.5
        expect(cell["open"].GetValue(c) in (0.0, 1.0), f"fracture piece {c} open")
        expect(cell["aperture"].GetValue(c) >= 0.0, f"fracture piece {c} aperture")
        if cell["open"].GetValue(c) == 0.0:
            expect(cell["aperture"].GetValue(c) == 0.0, f"closed fracture piece {c} has an aperture")
        # No [joint] hydraulic keys: the hydraulic aperture is the mechanical one.
        expect(cell["hydraulic_aperture"].GetValue(c) == cell["aperture"].GetValue(c),
               f"fracture piece {c} hydraulic aperture")
    expect(sorted(lengths) == [0, 1], f"fracture ids {sorted(lengths)}, expected [0, 1]")
    for f, length in lengths.items():
        expect(abs(length - 1.0) <= 1e-6, f"fracture {f} is {length} m long, expected 1 m")
    print("fractures consistent")
    print("ok")


if __name__ == "__main__":
    main()
