#!/usr/bin/env python3
"""The table of docs/studies/2026-11-29-sneddon-crack.md: the opening at the centre of the crack
of scenarios/verification/sneddon_crack.toml against Sneddon's w(0) = 4 (1 - nu^2) p a / E,
held by the flow (the shipped coupled run) and, by the same plate's mechanics alone, under a
remote tension sigma = p at its top (the same opening in an elastic continuum), over the
penalty, the finest sub-block size and the kind of sub-blocks.

    scripts/sneddon_crack_study.py build/bin/hydrodda [--out DIR]
"""
import argparse
import json
import pathlib
import re
import subprocess
import tempfile

SCENARIO = pathlib.Path(__file__).resolve().parent.parent / "scenarios/verification/sneddon_crack.toml"
SNEDDON = 4.0 * (1.0 - 0.25**2) * 1.0e6 * 1.0 / 1.0e10


def mechanics_alone(text):
    """The plate without its flow, pulled at its top by sigma = p."""
    text = text[: text.index("[flow]")] + text[text.index("[output]") :]
    text = text.replace("residual_aperture = 1.0e-5\n", "")
    return text.replace(
        '[[mechanics.measure]]\nname = "above"',
        '[[mechanics.traction]]\nboundary = "top"\nnormal = 1.0e6\nshear = 0.0\n\n[[mechanics.measure]]\nname = "above"',
    )


def variant(text, penalty=None, finest=None, kind=None):
    if penalty:
        text = text.replace("penalty = 1.0e13", f"penalty = {penalty}")
    if finest:
        text = text.replace("size = 0.1\n", f"size = {finest}\n", 1)
    if kind:
        text = re.sub(r"^size = (.*)$", rf'size = \1\nkind = "{kind}"', text, flags=re.M)
    return text


def opening(program, text, folder):
    scenario = folder / "case.toml"
    scenario.write_text(text)
    out = folder / "out"
    subprocess.run([program, "run", str(scenario), "-o", str(out), "--threads", "1", "-q", "--overwrite"], check=False)
    measure = json.loads((out / "summary.json").read_text())["measure"]
    return measure["above"]["displacement"][1] - measure["below"]["displacement"][1]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    args = parser.parse_args()
    shipped = SCENARIO.read_text()
    cases = [
        ("held by the flow (shipped)", shipped),
        ("remote tension", mechanics_alone(shipped)),
        ("remote tension, penalty 1e12", variant(mechanics_alone(shipped), penalty="1.0e12")),
        ("remote tension, penalty 1e11", variant(mechanics_alone(shipped), penalty="1.0e11")),
        ("remote tension, finest 0.05 m", variant(mechanics_alone(shipped), finest="0.05")),
        ("remote tension, triangles", variant(mechanics_alone(shipped), kind="triangles")),
    ]
    print("| case | w(0) (m) | w(0) / Sneddon's |\n| --- | --- | --- |")
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in cases:
            w = opening(args.program, text, pathlib.Path(tmp))
            print(f"| {name} | {w:.3g} | {w / SNEDDON:.3f} |", flush=True)


if __name__ == "__main__":
    main()
