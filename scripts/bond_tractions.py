#!/usr/bin/env python3
"""The traction on each intact bond's face near a point, as the DDA reads it to break the bond.

Reads a run or breach folder's last blocks_NNNN.vtu and bonds_NNNN.vtu (or those of --step N)
and prints, for each intact bond whose face's middle lies within REACH of (X, Y), the normal
traction sigma_n = n.s.n (tension positive) and the shear tau = t.s.n on its face, s the mean
stress of the face's two sub-blocks (docs/dda.md, "Bonds"), most tensile first.

    python3 scripts/bond_tractions.py FOLDER X Y REACH [--count 8] [--step N]

Standard library only (the .vtu reader of scripts/fracture_profile.py).
"""
import argparse
import glob
import importlib.util
import math
import os

spec = importlib.util.spec_from_file_location("fracture_profile", os.path.join(os.path.dirname(__file__), "fracture_profile.py"))
fracture_profile = importlib.util.module_from_spec(spec)
spec.loader.exec_module(fracture_profile)


def distance_to_segment(p, a, b):
    ex, ey = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / (ex * ex + ey * ey)))
    return math.hypot(a[0] + t * ex - p[0], a[1] + t * ey - p[1])


def face_tractions(folder, point, reach, step=None):
    name = f"{folder}/blocks_{step:04d}.vtu" if step is not None else sorted(glob.glob(f"{folder}/blocks_*.vtu"))[-1]
    blocks = fracture_profile.read_vtu(name)
    polygons, stress = fracture_profile.polygons(blocks), blocks["stress"]
    bonds = fracture_profile.read_vtu(name.replace("blocks_", "bonds_"))
    rows = []
    for k, ((ax, ay), (bx, by)) in enumerate(fracture_profile.polygons(bonds)):
        middle = ((ax + bx) / 2, (ay + by) / 2)
        if bonds["broken"][k] > 0 or math.dist(middle, point) > reach:
            continue
        sides = [b for b, p in enumerate(polygons)
                 if any(distance_to_segment(middle, p[i], p[(i + 1) % len(p)]) < 1e-3 for i in range(len(p)))]
        if len(sides) != 2:
            continue
        sx, sy, txy = (sum(stress[3 * b + c] for b in sides) / 2 for c in range(3))
        length = math.hypot(bx - ax, by - ay)
        tx, ty = (bx - ax) / length, (by - ay) / length
        nx, ny = -ty, tx
        sigma_n = nx * nx * sx + ny * ny * sy + 2 * nx * ny * txy
        tau = tx * nx * sx + ty * ny * sy + (tx * ny + ty * nx) * txy
        rows.append((sigma_n, tau, int(bonds["bond"][k]), middle, length, sides))
    return sorted(rows, reverse=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder")
    parser.add_argument("x", type=float)
    parser.add_argument("y", type=float)
    parser.add_argument("reach", type=float)
    parser.add_argument("--count", type=int, default=8)
    parser.add_argument("--step", type=int)
    a = parser.parse_args()
    for sigma_n, tau, bond, (mx, my), length, sides in face_tractions(a.folder, (a.x, a.y), a.reach, a.step)[:a.count]:
        print(f"bond {bond:5d} at ({mx:.2f}, {my:.2f}), face {length:.2f} m: sigma_n {sigma_n / 1e6:8.3f} MPa, "
              f"tau {tau / 1e6:8.3f} MPa (sub-blocks {sides[0]}, {sides[1]})")


if __name__ == "__main__":
    main()
