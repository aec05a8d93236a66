"""Post-processing a run folder with NumPy and Matplotlib: the coupling history (history.csv)
and the blocks' displacements (summary.json) of a finished run, whichever program or script
wrote it.

    PYTHONPATH=build/python python3 examples/python/read_run_folder.py RUN_FOLDER [--out FIGURE]

Prints the convergence of each pass and the largest block displacement, and draws both into
FIGURE (default RUN_FOLDER/history.png).
"""

import argparse
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import hydrodda


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("--out", type=Path)
    args = parser.parse_args()

    history = hydrodda.read_history(args.folder)  # {column: array}
    summary = json.loads((args.folder / "summary.json").read_text())
    displacement = np.array([block["displacement"] for block in summary["blocks"]])  # (blocks, 2), m
    magnitude = np.hypot(displacement[:, 0], displacement[:, 1])
    largest = int(np.argmax(magnitude))

    x_name = next(iter(history))  # "iteration" (coupled) or "step" (mechanics only)
    print(f"{summary['title']}: {len(history[x_name])} {x_name}s, converged: {summary['converged']}")
    if "head_change" in history:
        for i, dh, du in zip(history["iteration"], history["head_change"], history["displacement_change"]):
            print(f"  pass {i:g}: head change {dh:.3e}, displacement change {du:.3e}")
    print(f"largest block displacement: {magnitude[largest]:.4e} m (block {summary['blocks'][largest]['id']})")

    figure, (left, right) = plt.subplots(1, 2, figsize=(9, 3.5))
    for column in ("head_change", "displacement_change", "max_displacement"):
        if column in history:
            left.semilogy(history[x_name], np.maximum(history[column], 1e-300), "o-", label=column)
    left.set_xlabel(x_name)
    left.legend()
    centroids = np.array([block["centroid"] for block in summary["blocks"]])
    right.quiver(centroids[:, 0], centroids[:, 1], displacement[:, 0], displacement[:, 1])
    right.set_aspect("equal")
    right.set_title("block displacements")
    figure.tight_layout()
    out = args.out or args.folder / "history.png"
    figure.savefig(out, dpi=120)
    print(f"figure: {out}")


if __name__ == "__main__":
    main()
