"""Ctrl-C stops a run from Python as it stops the program's: after the step or pass under way,
the run folder at the last finished one, summary.json written; then KeyboardInterrupt."""

import json
import os
import signal
import subprocess
import sys

import pytest

import hydrodda
from conftest import VERIFICATION


def test_ctrl_c_between_passes_stops_cleanly_and_resumes(in_tmp):
    scenario = hydrodda.Scenario.load(VERIFICATION / "coupled_hydrostatic_column.toml")

    def press_ctrl_c(report):
        if report.count == 1:
            signal.raise_signal(signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        hydrodda.run(scenario, "py", progress=press_ctrl_c)
    summary = json.loads((in_tmp / "py/summary.json").read_text())
    assert summary["iterations"] == 1 and not summary["converged"]
    assert summary["status"] != "ok"
    resumed = hydrodda.resume("py")
    whole = hydrodda.run(scenario, "whole")
    assert (resumed.status, resumed.iterations) == ("finished", whole.iterations)
    assert resumed.summary["blocks"] == whole.summary["blocks"]


CHILD = """
import sys, hydrodda
scenario = hydrodda.Scenario.load(sys.argv[1])
scenario.set("mechanics.end_time", 100.0)  # far longer than the test waits

def progress(report):
    if report.count == 1:
        print("started", flush=True)

try:
    hydrodda.run(scenario, "py", progress=progress)
except KeyboardInterrupt:
    print("KeyboardInterrupt", flush=True)
    sys.exit(130)
print("not interrupted", flush=True)
"""


def test_ctrl_c_while_the_run_holds_no_gil(in_tmp):
    """SIGINT from outside, while the C++ run is under way with the GIL released."""
    child = subprocess.Popen([sys.executable, "-c", CHILD, str(VERIFICATION / "free_fall.toml")], cwd=in_tmp,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=os.environ)
    try:
        assert child.stdout.readline().strip() == "started"
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
    finally:
        child.kill()
    assert child.returncode == 130, err
    assert out.strip() == "KeyboardInterrupt"
    summary = json.loads((in_tmp / "py/summary.json").read_text())
    assert 1 <= summary["iterations"] < 100000 and summary["status"] != "ok"
    assert "interrupt" in summary["message"]
