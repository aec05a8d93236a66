"""Reading a run folder's tables back into NumPy arrays."""

import csv
from pathlib import Path

import numpy as np


def read_history(folder):
    """history.csv of a run folder as {column name: 1-D float array}, in the file's order."""
    path = Path(folder) / "history.csv"
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty, expected a header line")
    header, body = rows[0], rows[1:]
    columns = {}
    for i, name in enumerate(header):
        columns[name] = np.array([float(row[i]) if row[i] != "" else np.nan for row in body], dtype=float)
    return columns
