#!/usr/bin/env python3
"""Along one fracture of a coupled run: the blocks' gap and the transmissivity the fluid mesh carries.

Reads one pass of a run folder (blocks_NNNN.vtu and fluid_NNNN.vtu, the last pass by default) and,
in bins along the fracture trace from A to B, prints
  - gap: the blocks' normal opening at the bin's middle (the distance between the two block
    faces met along the fracture's normal, within --reach of the trace),
  - cubic: the cubic-law transmissivity of that gap, gap^3 / 12 (m^3),
  - mesh: the transmissivity the fluid mesh represents there, the integral of (k - k_m) across
    the fracture, i.e. the sum of (k_e - k_m) A_e over the elements within --reach, per bin length,
  - flow: the Darcy flux along the fracture summed over the same elements, per bin length (m^2/s).
k_m is the smallest element permeability. Comparing two runs that differ only in mesh.fracture_size
separates what the mechanics changed (gap) from what the mesh made of it (mesh against cubic).

    python3 scripts/fracture_profile.py RUN_FOLDER X0 Y0 X1 Y1 [--bin 0.25] [--reach 0.02] [--pass N]

Standard library only (the .vtu files are ParaView's layout: appended raw data, zlib, UInt64 headers).
"""
import argparse
import glob
import math
import os
import re
import struct
import zlib

FORMATS = {"Float64": "d", "Int64": "q", "UInt8": "B"}


def read_vtu(path):
    raw = open(path, "rb").read()
    start = raw.index(b"<AppendedData")
    data = raw[raw.index(b"_", start) + 1:]
    arrays = {}
    pattern = r'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="\d+" format="appended" offset="(\d+)"'
    for m in re.finditer(pattern, raw[:start].decode()):
        kind, name, offset = m.group(1), m.group(2), int(m.group(3))
        blocks = struct.unpack_from("<Q", data, offset)[0]
        sizes = struct.unpack_from(f"<{blocks}Q", data, offset + 24)
        p, buf = offset + 24 + 8 * blocks, b""
        for size in sizes:
            buf += zlib.decompress(data[p:p + size])
            p += size
        fmt = FORMATS[kind]
        arrays[name] = struct.unpack(f"<{len(buf) // struct.calcsize(fmt)}{fmt}", buf)
    return arrays


def polygons(arrays):
    pts, conn, result, start = arrays["Points"], arrays["connectivity"], [], 0
    for end in arrays["offsets"]:
        result.append([(pts[3 * i], pts[3 * i + 1]) for i in conn[start:end]])
        start = end
    return result


def inside(poly, x, y):
    result = False
    for i in range(len(poly)):
        (ax, ay), (bx, by) = poly[i], poly[(i + 1) % len(poly)]
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            result = not result
    return result


def normal_gap(blocks, mid, normal, reach):
    """The open gap between two block faces met along `normal` through `mid`, the one nearest
    `mid` within `reach` (0 where the faces touch or overlap)."""
    hits = []
    for b, poly in enumerate(blocks):
        for i in range(len(poly)):
            (ax, ay), (bx, by) = poly[i], poly[(i + 1) % len(poly)]
            ex, ey = bx - ax, by - ay
            det = -normal[0] * ey + normal[1] * ex
            if det == 0.0:
                continue
            rx, ry = ax - mid[0], ay - mid[1]
            t = (-rx * ey + ry * ex) / det  # distance along the normal
            u = (normal[0] * ry - normal[1] * rx) / det  # position along the edge
            if 0.0 <= u <= 1.0 and abs(t) <= reach:
                hits.append((t, b))
    hits.sort()
    best = None
    for (t0, b0), (t1, b1) in zip(hits, hits[1:]):
        middle = (t0 + t1) / 2
        x, y = mid[0] + middle * normal[0], mid[1] + middle * normal[1]
        if b0 != b1 and t1 > t0 and not any(inside(poly, x, y) for poly in blocks):
            if best is None or abs(middle) < abs(best[0]):
                best = (middle, t1 - t0)
    return best[1] if best else 0.0


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run")
    p.add_argument("ends", nargs=4, type=float, metavar="X0 Y0 X1 Y1")
    p.add_argument("--bin", type=float, default=0.25)
    p.add_argument("--reach", type=float, default=0.02)
    p.add_argument("--pass", dest="step", type=int)
    args = p.parse_args()
    suffix = f"_{args.step:04d}.vtu" if args.step else None
    fluid = sorted(glob.glob(os.path.join(args.run, "fluid_*.vtu")))
    blocks = sorted(glob.glob(os.path.join(args.run, "blocks_*.vtu")))
    if suffix:
        fluid = [f for f in fluid if f.endswith(suffix)]
        blocks = [f for f in blocks if f.endswith(suffix)]
    if not fluid or not blocks:
        raise SystemExit(f"{args.run}: no fluid_*.vtu and blocks_*.vtu for that pass")
    mesh, shapes = read_vtu(fluid[-1]), polygons(read_vtu(blocks[-1]))
    x0, y0, x1, y1 = args.ends
    length = math.hypot(x1 - x0, y1 - y0)
    tangent = ((x1 - x0) / length, (y1 - y0) / length)
    normal = (-tangent[1], tangent[0])
    k, flux, pts, conn = mesh["permeability"], mesh["flux"], mesh["Points"], mesh["connectivity"]
    k_matrix = min(k)
    bins = int(math.ceil(length / args.bin))
    carried, flow = [0.0] * bins, [0.0] * bins
    for e in range(len(k)):
        a, b, c = conn[3 * e:3 * e + 3]
        xs = (pts[3 * a], pts[3 * b], pts[3 * c])
        ys = (pts[3 * a + 1], pts[3 * b + 1], pts[3 * c + 1])
        area = abs((xs[1] - xs[0]) * (ys[2] - ys[0]) - (xs[2] - xs[0]) * (ys[1] - ys[0])) / 2
        cx, cy = sum(xs) / 3 - x0, sum(ys) / 3 - y0
        s, n = cx * tangent[0] + cy * tangent[1], cx * normal[0] + cy * normal[1]
        if abs(n) < args.reach and 0.0 <= s < length:
            i = min(int(s / args.bin), bins - 1)
            carried[i] += (k[e] - k_matrix) * area / args.bin
            flow[i] += (flux[3 * e] * tangent[0] + flux[3 * e + 1] * tangent[1]) * area / args.bin
    print(f"# {fluid[-1]}  k_m = {k_matrix:.4g} m^2")
    print("| s (m) | gap (um) | cubic (m^3) | mesh (m^3) | flow (m^2/s) |")
    print("| ---: | ---: | ---: | ---: | ---: |")
    for i in range(bins):
        s = (i + 0.5) * args.bin
        mid = (x0 + s * tangent[0], y0 + s * tangent[1])
        gap = normal_gap(shapes, mid, normal, args.reach)
        print(f"| {s:.3f} | {gap * 1e6:.1f} | {gap ** 3 / 12:.3g} | {carried[i]:.3g} | {flow[i]:.3g} |")


if __name__ == "__main__":
    main()
