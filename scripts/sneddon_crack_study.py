#!/usr/bin/env python3
"""The tables of docs/studies/2026-11-29-sneddon-crack-at-rest.md: the opening of the crack of
scenarios/verification/sneddon_crack.toml against Sneddon's w(s) = 4 (1 - nu^2) p / E sqrt(a^2 - s^2)
at its centre (s = 0.001 m) and at s = a/2, by the plate's mechanics alone under a remote
tension sigma = p at its top (the same opening in an elastic continuum), stepped to rest, at
three sizes of the sub-blocks about the crack (the finest h and the next ring 2 h), Voronoi cells
and triangles; then the shipped coupled run, held by the flow.

    scripts/sneddon_crack_study.py build/bin/hydrodda [--only mechanics|flow]
"""
import argparse
import json
import math
import pathlib
import re
import subprocess
import tempfile
import time

SCENARIO = pathlib.Path(__file__).resolve().parent.parent / "scenarios/verification/sneddon_crack.toml"
W0 = 4.0 * (1.0 - 0.25**2) * 1.0e6 * 1.0 / 1.0e10  # Sneddon's w(0), m
STEPS = 80  # static steps of the mechanics alone; the opening over the last ten is reported


def mechanics_alone(text):
    """The plate without its flow, pulled at its top by sigma = p, stepped STEPS times."""
    text = text[: text.index("[flow]")] + text[text.index("[output]") :]
    text = text.replace("residual_aperture = 1.0e-5\n", "")
    text = re.sub(r"^steps = \d+$", f"steps = {STEPS}", text, flags=re.M)
    return text.replace(
        '[[mechanics.measure]]\nname = "above"',
        '[[mechanics.traction]]\nboundary = "top"\nnormal = 1.0e6\nshear = 0.0\n\n[[mechanics.measure]]\nname = "above"',
    )


def with_sizes(text, finest, kind):
    """The two inner tables' sizes h and 2 h, every table's kind."""
    sizes = iter([finest, 2.0 * finest])
    text = re.sub(r"^size = 0\.[12]\n", lambda m: f"size = {next(sizes)}\n", text, count=2, flags=re.M)
    return re.sub(r'^kind = ".*"\n', "", text, flags=re.M).replace(
        'joint = "bond"\n', f'kind = "{kind}"\njoint = "bond"\n'
    )


def run(program, text, folder):
    scenario = folder / "case.toml"
    scenario.write_text(text)
    out = folder / "out"
    start = time.time()
    subprocess.run([program, "run", str(scenario), "-o", str(out), "--threads", "1", "-q", "--overwrite"], check=False)
    return out, time.time() - start


def openings_by_step(out):
    """{step: {name: uy}} from measure.csv."""
    rows = {}
    lines = (out / "measure.csv").read_text().splitlines()
    head = lines[0].split(",")
    for line in lines[1:]:
        r = dict(zip(head, line.split(",")))
        rows.setdefault(int(r["step"]), {})[r["name"]] = float(r["uy"])
    return rows


def mechanics_table(program, tmp):
    print("| kind | h | sub-blocks | w(0) / Sneddon's | w(a/2) / Sneddon's | change over the last 10 steps |")
    print("| --- | --- | --- | --- | --- | --- |")
    shipped = SCENARIO.read_text()
    for kind in ("triangles", "voronoi"):
        for finest in (0.2, 0.1, 0.05):
            out, _ = run(program, with_sizes(mechanics_alone(shipped), finest, kind), tmp)
            rows = openings_by_step(out)
            last = max(rows)
            w0 = rows[last]["above"] - rows[last]["below"]
            w_half = rows[last]["above_half"] - rows[last]["below_half"]
            before = rows[last - 10]["above"] - rows[last - 10]["below"]
            blocks = len(json.loads((out / "summary.json").read_text())["blocks"])
            print(
                f"| {kind} | {finest} | {blocks} | {w0 / W0:.4f} | {w_half / (W0 * math.sqrt(0.75)):.4f} | {abs(w0 - before) / W0:.1e} |",
                flush=True,
            )


def flow_row(program, tmp):
    out, cpu = run(program, SCENARIO.read_text(), tmp)
    summary = json.loads((out / "summary.json").read_text())
    m = summary["measure"]
    w0 = m["above"]["displacement"][1] - m["below"]["displacement"][1]
    w_half = m["above_half"]["displacement"][1] - m["below_half"]["displacement"][1]
    print(f"held by the flow (shipped): w(0) / Sneddon's {w0 / W0:.4f}, w(a/2) / Sneddon's "
          f"{w_half / (W0 * math.sqrt(0.75)):.4f}, converged {summary.get('converged')}, "
          f"{summary.get('iterations', '')} passes, {cpu:.0f} s wall clock")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("--only", choices=["mechanics", "flow"])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        if args.only != "flow":
            mechanics_table(args.program, pathlib.Path(tmp))
        if args.only != "mechanics":
            flow_row(args.program, pathlib.Path(tmp))


if __name__ == "__main__":
    main()
