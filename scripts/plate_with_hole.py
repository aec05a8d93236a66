#!/usr/bin/env python3
"""Writes scenarios/verification/plate_with_hole.toml: a quarter of a plate with a hole of
radius a under a remote tension sigma along y, its far edges loaded by Kirsch's own tractions.

    scripts/plate_with_hole.py > scenarios/verification/plate_with_hole.toml

Kirsch (1898), a hole of radius a in an infinite plate under sigma along x (Timoshenko &
Goodier, Theory of Elasticity, 3rd ed., section 35), polar (r, theta from the load):
  s_rr = s/2 (1 - a2/r2) + s/2 (1 - 4 a2/r2 + 3 a4/r4) cos 2t
  s_tt = s/2 (1 + a2/r2) - s/2 (1 + 3 a4/r4) cos 2t
  s_rt = -s/2 (1 + 2 a2/r2 - 3 a4/r4) sin 2t
Here the load is along y: the field at (x, y) is the one above at (y, x), x and y swapped.
"""
import math

A = 1.0           # the hole's radius (m)
W = 8.0           # the quarter plate's side (m)
SIGMA = 1.0e6     # the remote tension (Pa)
ARC = 16          # segments of the hole's quarter arc


def kirsch_along_x(x, y):
    """(sxx, syy, sxy) of Kirsch's field under SIGMA along x."""
    r2 = x * x + y * y
    t = math.atan2(y, x)
    q, q2 = A * A / r2, (A * A / r2) ** 2
    c, s = math.cos(2 * t), math.sin(2 * t)
    srr = SIGMA / 2 * (1 - q) + SIGMA / 2 * (1 - 4 * q + 3 * q2) * c
    stt = SIGMA / 2 * (1 + q) - SIGMA / 2 * (1 + 3 * q2) * c
    srt = -SIGMA / 2 * (1 + 2 * q - 3 * q2) * s
    ct, st = math.cos(t), math.sin(t)
    sxx = srr * ct * ct + stt * st * st - 2 * srt * st * ct
    syy = srr * st * st + stt * ct * ct + 2 * srt * st * ct
    sxy = (srr - stt) * st * ct + srt * (ct * ct - st * st)
    return sxx, syy, sxy


def kirsch(x, y):
    """(sxx, syy, sxy) at (x, y) under SIGMA along y."""
    sxx, syy, sxy = kirsch_along_x(y, x)
    return syy, sxx, sxy


def arc_points():
    """The hole's arc from (0, a) to (a, 0), clockwise, its ends included."""
    angles = [math.pi / 2 * k / ARC for k in range(ARC + 1)]
    return [(round(A * math.sin(t), 12) + 0.0, round(A * math.cos(t), 12) + 0.0) for t in angles]


def ray_to_edge(p):
    """Where the ray from the hole's centre through p leaves the square [0, W]^2."""
    scale = W / max(p[0], p[1])
    return (round(p[0] * scale, 12), round(p[1] * scale, 12))


def far_edge_pieces(arc):
    """The far edges cut where the sectors' traces meet them: (y0, y1) pieces of x = W, (x0, x1) of y = W."""
    ends = [ray_to_edge(p) for p in arc[1:-1]]
    ys = sorted({0.0, W} | {e[1] for e in ends if e[0] == W})
    xs = sorted({0.0, W} | {e[0] for e in ends if e[1] == W})
    return list(zip(ys, ys[1:])), list(zip(xs, xs[1:]))


def pa(value):
    """A stress in Pa to 7 digits, round-off about zero written as 0."""
    return "0.0" if abs(value) < 1e-3 else f"{value:.6e}"


def fmt(p):
    return f"[{p[0]:.12g}, {p[1]:.12g}]"


def main():
    arc = arc_points()
    domain = [arc[-1], (W, 0.0), (W, W), (0.0, W)] + arc[:-1]
    print(HEADER)
    print("[geometry]")
    print("domain = [" + ", ".join(fmt(p) for p in domain) + "]")
    print()
    for p in arc[1:-1]:
        print("[[geometry.fracture]]")
        print(f"trace = [{fmt(p)}, {fmt(ray_to_edge(p))}]")
        print('joint = "glue"\n')
    print(BODY)
    print("[boundaries]")
    right, top = far_edge_pieces(arc)
    for k, (y0, y1) in enumerate(right):
        print(f"right{k} = {{ from = [{W:g}, {y0:.12g}], to = [{W:g}, {y1:.12g}] }}")
    for k, (x0, x1) in enumerate(top):
        print(f"top{k} = {{ from = [{x0:.12g}, {W:g}], to = [{x1:.12g}, {W:g}] }}")
    print()
    for k, (y0, y1) in enumerate(right):  # outward normal +x: normal sxx; shear along the outline (+y): sxy
        s0, s1 = kirsch(W, y0), kirsch(W, y1)
        print(f'[[mechanics.traction]]\nboundary = "right{k}"')
        print(f"normal = {pa(s0[0])}\nnormal_end = {pa(s1[0])}\nshear = {pa(s0[2])}\nshear_end = {pa(s1[2])}\n")
    for k, (x0, x1) in enumerate(top):  # outward normal +y: normal syy; shear along the outline, -x: -sxy
        s0, s1 = kirsch(x0, W), kirsch(x1, W)
        print(f'[[mechanics.traction]]\nboundary = "top{k}"')
        print(f"normal = {pa(s0[1])}\nnormal_end = {pa(s1[1])}\nshear = {pa(-s0[2])}\nshear_end = {pa(-s1[2])}\n")
    print(TAIL)


HEADER = '''title = "Verification: a plate with a hole under tension (Kirsch), bonded triangle sub-blocks"
# Written by scripts/plate_with_hole.py (edit that, not this file).
# A quarter of a plate with a hole of radius a = 1 m under a remote tension sigma = 1 MPa along
# y, plane strain, no gravity: the square [0, 8 a]^2 less the hole, whose quarter arc is a
# polygon of 16 segments. Rollers on the two symmetry lines x = 0 and y = 0; the far edges
# x = 8 a and y = 8 a loaded by Kirsch's own tractions (sigma . n of the field below, linear
# along each piece between the sectors' corners), so that the answer is Kirsch's with no
# correction for the plate's finite width. Kirsch (1898; Timoshenko & Goodier, Theory of
# Elasticity, 3rd ed., section 35): on the symmetry line y = 0
#   sigma_yy(x, 0) = sigma (1 + a^2 / (2 x^2) + 3 a^4 / (2 x^4)),
# 3 sigma at the hole's edge, and the ligament from x = a to 2 a carries 1.6875 sigma a.
# The sub-blocks are bonded triangles (constant-strain triangles, which converge to the elastic
# continuum; docs/dda.md, "Bonds"), a/10 within 2.5 a of the hole, a/5 within 4 a, then a/2; no
# bond breaks. The plate is cut into 16 convex sectors by rays from the hole's centre through
# the arc's corners, each tessellated on its own, their faces held together by a joint as
# strong as the bonds (`glue`: its contacts stay locked, and the sectors' sub-blocks need not
# meet corner to corner); the plate as one block that is not convex would tessellate too.
# tests/verification/bonded_continuum_verification_test.cpp runs it at h = a/2.5, a/5 and a/10
# (this file): the ligament's force, the sub-blocks' sigma_yy times their faces' lengths on
# y = 0, is 0.644, 0.930, 0.962 of Kirsch's, the error falling at each halving, the finest
# within 5%; at a/20 0.987 (docs/studies/2026-11-30-bonds-against-the-continuum.md).'''

BODY = '''[[geometry.tessellate]]
size = 0.1
region = [[0.0, 0.0], [2.5, 0.0], [2.5, 2.5], [0.0, 2.5]]
kind = "triangles"
joint = "bond"
seed = 1

[[geometry.tessellate]]
size = 0.2
region = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]
kind = "triangles"
joint = "bond"
seed = 2

[[geometry.tessellate]]
size = 0.5
kind = "triangles"
joint = "bond"
seed = 3

[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25

[joint.bond]
tensile_strength = 1.0e9
cohesion = 1.0e9
friction_angle = 30.0

[joint.glue]
tensile_strength = 1.0e9
cohesion = 1.0e9
friction_angle = 30.0

[mechanics]
# 40 static steps: at rest (the program's test) well before the last.
analysis = "static"
plane = "strain"
gravity = [0.0, 0.0]
time_step = 1.0
steps = 40
penalty = 1.0e13

[[mechanics.roller]]
boundary = "left"

[[mechanics.roller]]
boundary = "bottom"

[[mechanics.measure]]
name = "hole_top"
point = [0.0, 1.0]
'''

TAIL = '''[output]
every = 1000'''

if __name__ == "__main__":
    main()
