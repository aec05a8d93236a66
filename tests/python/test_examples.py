"""The examples under examples/python/ run as a user runs them (Matplotlib's Agg backend)."""

import json
import os
import re
import subprocess
import sys

from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples/python"


def run_example(name, *arguments, cwd):
    done = subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, arguments)], cwd=cwd,
                          capture_output=True, text=True, timeout=300, env=os.environ)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_fig9_loop_then_post_processing(in_tmp):
    out = run_example("fig9_heads.py", "--heads", "5", "20", "--out", "fig9", cwd=in_tmp)
    # docs/paper.md's Fig. 9 table, from `hydrodda sweep` over the same heads: 1.0008 at 5 m,
    # 1.0099 at 20 m (printed to 4 decimals).
    ratios = [float(r) for r in re.findall(r"K_eff / K_matrix = ([0-9.]+)", out)]
    assert ratios == [1.0008, 1.0099]
    for head, ratio in zip(["5", "20"], ratios):
        summary = json.loads((in_tmp / f"fig9/head_{head}m/summary.json").read_text())
        assert summary["converged"]
        assert round(summary["flow"]["regions"]["fractured"]["normalised_conductivity"], 4) == ratio
    assert (in_tmp / "fig9/fig9.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"

    out = run_example("read_run_folder.py", "fig9/head_20m", "--out", "history.png", cwd=in_tmp)
    summary = json.loads((in_tmp / "fig9/head_20m/summary.json").read_text())
    assert f"{summary['iterations']} iterations, converged: True" in out
    assert len(re.findall(r"^  pass \d+:", out, re.MULTILINE)) == summary["iterations"]
    largest = max((b["displacement"][0] ** 2 + b["displacement"][1] ** 2) ** 0.5 for b in summary["blocks"])
    assert f"largest block displacement: {largest:.4e} m" in out
    assert (in_tmp / "history.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
