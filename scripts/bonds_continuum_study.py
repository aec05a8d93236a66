#!/usr/bin/env python3
"""The tables of docs/studies/2026-11-30-bonds-against-the-continuum.md: bonded sub-blocks
against the elastic continuum at three sizes and more, triangles and Voronoi cells.

- scenarios/verification/plate_with_hole.toml (Kirsch): the force the ligament from the hole's
  edge x = a to x = 2a on the symmetry line y = 0 carries, the sum of sigma_yy times length over
  the sub-blocks' faces on that line, against Kirsch's 1.6875 sigma a; the same over the whole
  line from a to W against the far edges' load (an equilibrium check); sigma_yy of the sub-block
  at the hole's edge against 3 sigma. The two inner tables' sizes are h and 2 h.
- scenarios/verification/bonded_cantilever.toml: the tip's deflection against Timoshenko's beam,
  P L^3 / (3 E I) + P L / (kappa G A), kappa = 5/6; and the same beam cut by three slanted
  seams of the clamp's joint (each piece tessellated on its own), the plate's glued sectors' share.

    scripts/bonds_continuum_study.py build/bin/hydrodda [--only plate|cantilever|seams]
"""
import argparse
import glob
import json
import pathlib
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from fracture_profile import polygons, read_vtu  # noqa: E402

VERIFICATION = pathlib.Path(__file__).resolve().parent.parent / "scenarios/verification"
A, W, SIGMA = 1.0, 8.0, 1.0e6
KIRSCH_LIGAMENT = 1.6875 * SIGMA * A  # the integral of Kirsch's sigma_yy(x, 0) from a to 2a
# The same from a to W: sigma ((W - a) + a^2/2 (1/a - 1/W) + a^4/2 (1/a^3 - 1/W^3)).
KIRSCH_LINE = SIGMA * ((W - A) + A * A / 2 * (1 / A - 1 / W) + A**4 / 2 * (1 / A**3 - 1 / W**3))
P, L, DEPTH, E, NU = 5.0e3, 8.0, 1.0, 1.0e10, 0.25  # the cantilever, plane stress
G = E / (2 * (1 + NU))
BEAM = P * L**3 / (3 * E * DEPTH**3 / 12) + P * L / (5 / 6 * G * DEPTH)


def run(program, text, folder):
    scenario = folder / "case.toml"
    scenario.write_text(text)
    out = folder / "out"
    start = time.time()
    subprocess.run([program, "run", str(scenario), "-o", str(out), "--threads", "1", "-q", "--overwrite"],
                   check=False, stderr=subprocess.DEVNULL)
    return out, time.time() - start


def with_kind(text, kind):
    return text.replace('kind = "triangles"', f'kind = "{kind}"')


def plate_sizes(text, finest):
    """The plate's two inner tables' sizes h and 2 h."""
    sizes = iter([finest, 2.0 * finest])
    return re.sub(r"^size = 0\.[12]\n", lambda m: f"size = {next(sizes)}\n", text, count=2, flags=re.M)


def on_the_line(out):
    """(force over a..2a, force over a..W, sigma_yy at the hole's edge) from the faces on y = 0."""
    first = read_vtu(out / "blocks_0000.vtu")
    last = read_vtu(pathlib.Path(sorted(glob.glob(str(out / "blocks_*.vtu")))[-1]))
    ligament = line = 0.0
    edge = None
    for c, poly in enumerate(polygons(first)):
        syy = last["stress"][3 * c + 1]
        for (ax, ay), (bx, by) in zip(poly, poly[1:] + poly[:1]):
            if abs(ay) > 1e-9 or abs(by) > 1e-9:
                continue
            lo, hi = min(ax, bx), max(ax, bx)
            line += syy * (hi - lo)
            ligament += syy * max(0.0, min(hi, 2 * A) - max(lo, A))
            if abs(lo - A) < 1e-9:
                edge = syy
    return ligament, line, edge


def plate_table(program, tmp):
    print("| kind | h | sub-blocks | ligament a..2a / Kirsch's | line a..W / its load | sigma_yy at the hole's edge / sigma | s |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    shipped = (VERIFICATION / "plate_with_hole.toml").read_text()
    for kind in ("triangles", "voronoi"):
        for h in (0.4, 0.2, 0.1, 0.05):
            out, seconds = run(program, with_kind(plate_sizes(shipped, h), kind), tmp)
            summary = json.loads((out / "summary.json").read_text())
            ligament, line, edge = on_the_line(out)
            print(f"| {kind} | {h} | {len(summary['blocks'])} | {ligament / KIRSCH_LIGAMENT:.4f} | "
                  f"{line / KIRSCH_LINE:.4f} | {edge / SIGMA:.3f} | {seconds:.1f} |"
                  + ("" if summary.get("converged") else " (not at rest)"), flush=True)


def with_seams(text):
    """The beam cut by three slanted traces of the clamp's joint, each side tessellated on its
    own: seams glued as the plate's sectors are."""
    seams = "".join(f'[[geometry.fracture]]\ntrace = [[{x}, -0.5], [{x + 0.3}, 0.5]]\njoint = "clamp"\n\n'
                    for x in (2.0, 4.0, 6.0))
    return text.replace("[[geometry.tessellate]]", seams + "[[geometry.tessellate]]", 1)


def cantilever_table(program, tmp, seams=False):
    if seams:
        print("The cantilever cut by three glued seams:")
    print("| kind | h | sub-blocks | tip deflection / Timoshenko's | s |")
    print("| --- | --- | --- | --- | --- |")
    shipped = (VERIFICATION / "bonded_cantilever.toml").read_text()
    if seams:
        shipped = with_seams(shipped)
    for kind in ("triangles",) if seams else ("triangles", "voronoi"):
        for h in (0.5, 0.25, 0.125, 0.0625):
            text = re.sub(r"^size = 0\.125\n", f"size = {h}\n", with_kind(shipped, kind), count=1, flags=re.M)
            out, seconds = run(program, text, tmp)
            summary = json.loads((out / "summary.json").read_text())
            tip = -summary["measure"]["tip"]["displacement"][1]
            print(f"| {kind} | {h} | {len(summary['blocks'])} | {tip / BEAM:.4f} | {seconds:.1f} |"
                  + ("" if summary.get("converged") else " (not at rest)"), flush=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("--only", choices=["plate", "cantilever", "seams"])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        if args.only in (None, "plate"):
            plate_table(args.program, pathlib.Path(tmp))
        if args.only in (None, "cantilever"):
            cantilever_table(args.program, pathlib.Path(tmp))
        if args.only in (None, "seams"):
            cantilever_table(args.program, pathlib.Path(tmp), seams=True)


if __name__ == "__main__":
    main()
