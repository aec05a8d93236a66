"""Ctrl-C stops a run from Python as it stops the program's: after the step or pass under way,
the run folder at the last finished one, summary.json written; then KeyboardInterrupt."""

import json
import logging
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
scenario.set("mechanics.end_time", 1.0e5)  # 10^8 steps: it cannot end before the signal comes

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
    assert 1 <= summary["iterations"] < 100000000 and summary["status"] != "ok"
    assert "interrupt" in summary["message"]


class CtrlCOnALine(logging.Handler):
    """Presses Ctrl-C while the logger "hydrodda" handles a message that starts with `start` and
    ends with `end`: Python's handler raises KeyboardInterrupt inside this handler."""

    def __init__(self, start, end):
        super().__init__(logging.DEBUG)
        self.start, self.end = start, end
        self.pressed = 0

    def emit(self, record):
        message = record.getMessage()
        if message.startswith(self.start) and message.endswith(self.end) and not self.pressed:
            self.pressed += 1
            signal.raise_signal(signal.SIGINT)


@pytest.fixture
def ctrl_c_while_meshing():
    """Ctrl-C on the line a run logs as it starts to mesh ("mesh: ... expected")."""
    handler = CtrlCOnALine("mesh: ", " expected")
    logger = logging.getLogger("hydrodda")
    level = logger.level
    logger.setLevel(logging.DEBUG)
    logger.addHandler(handler)
    yield handler
    logger.removeHandler(handler)
    logger.setLevel(level)


def test_ctrl_c_while_meshing_stops_the_run(in_tmp, ctrl_c_while_meshing):
    """The KeyboardInterrupt raised in the logging handler used to be dropped with the handler's
    error: the run went on to "finished". Now the run stops before its first pass, as at Ctrl-C
    between passes (with no pass to resume from), and raises it."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "coupled_hydrostatic_column.toml")
    with pytest.raises(KeyboardInterrupt):
        hydrodda.run(scenario, "py")
    assert ctrl_c_while_meshing.pressed == 1
    summary = json.loads((in_tmp / "py/summary.json").read_text())
    assert (summary["status"], summary["iterations"], summary["converged"]) == ("interrupted", 0, False)


def test_ctrl_c_while_a_simulation_meshes_is_raised_once_it_is_built(ctrl_c_while_meshing):
    scenario = hydrodda.Scenario.load(VERIFICATION / "coupled_hydrostatic_column.toml")
    with pytest.raises(KeyboardInterrupt):
        hydrodda.Simulation(scenario)
    assert ctrl_c_while_meshing.pressed == 1
