"""Python threads: one Simulation called from two of them, and two runs side by side, each
giving what it gives alone, bit for bit."""

import logging
import os
import subprocess
import sys
import threading

import numpy as np
import pytest

import hydrodda
from conftest import SOURCE_DIR, VERIFICATION

# The second thread calls once the first is inside its steps, without a clock: the first keeps
# the GIL (no forced switch with an interval of 1000 s) until step() releases it, holding the
# model, and only then can the second, woken before, run.
SECOND_CALLER = """
import sys, threading, hydrodda
sys.setswitchinterval(1000)
scenario = hydrodda.Scenario.load(sys.argv[1])
scenario.set("mechanics.steps", 1000)
steps = 200
sim = hydrodda.Simulation(scenario)
woken = threading.Event()
second = {}

def step_once():
    woken.wait()
    second["taken"] = sim.step(1)
    second["steps_after"] = sim.summary["iterations"]

thread = threading.Thread(target=step_once)
thread.start()
woken.set()
first = sim.step(steps)
thread.join()
alone = hydrodda.Simulation(scenario)
alone.step(steps + 1)
print(first, second["taken"], second["steps_after"],
      (sim.blocks["displacement"] == alone.blocks["displacement"]).all())
"""


def test_a_second_thread_waits_for_the_steps_under_way(in_tmp):
    """Without the model's lock the second thread steps the model while the first does: a
    crash (SIGSEGV) or blocks moved by two steps at once (its step came 12th). With it the
    second call waits: its step is the 201st, and the model ends where 201 steps on one thread
    leave it."""
    child = subprocess.run([sys.executable, "-c", SECOND_CALLER, str(VERIFICATION / "brick_wall_determinism.toml")],
                           cwd=in_tmp, capture_output=True, text=True, env=os.environ, timeout=600)
    assert child.returncode == 0, child.stderr
    assert child.stdout.split() == ["200", "1", "201", "True"]


def test_runs_side_by_side_equal_a_run_alone(in_tmp):
    """Two runs in two threads, with a third meshing beside them until both are done, give what
    a run alone gives, bit for bit. METIS draws from one random number generator per process,
    and Gmsh orders with the same METIS: without a lock around every call into either, one
    thread's meshing or ordering moves the other's order of the flow matrix, and its heads at
    round-off (K_eff 9.69634255907e-09 against 9.69634337430e-09 on a seal)."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "flow_three_fractures.toml")
    alone = hydrodda.run(scenario, "alone")
    results = {}
    runs_done = threading.Barrier(3)

    def run(name):
        try:
            results[name] = hydrodda.run(scenario, name)
        finally:
            runs_done.wait()

    def mesh_until_the_runs_are_done():
        mesher = hydrodda.Scenario.load(VERIFICATION / "flow_linear_head.toml")
        while runs_done.n_waiting < 2:
            hydrodda.Simulation(mesher)
        runs_done.wait()

    threads = [threading.Thread(target=run, args=(name,)) for name in ("first", "second")]
    threads.append(threading.Thread(target=mesh_until_the_runs_are_done))
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for name in ("first", "second"):
        result = results[name]
        assert result.status == "finished"
        np.testing.assert_array_equal(result.fluid["head"], alone.fluid["head"])
        assert result.summary["flow"] == alone.summary["flow"]


class CallOnALine(logging.Handler):
    """Calls `call` while the logger "hydrodda" handles a line that contains `text`; keeps what
    it raised."""

    def __init__(self, text, call):
        super().__init__(logging.WARNING)
        self.text, self.call = text, call
        self.raised = []

    def emit(self, record):
        if self.text in record.getMessage():
            try:
                self.call()
            except RuntimeError as error:
                self.raised.append(str(error))


def test_a_handler_inside_a_call_cannot_call_its_simulation():
    """A logging handler runs inside the Simulation's own call, on its thread: its call into
    the same model would wait for the call that runs it, so it is refused (RuntimeError)."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "flow_linear_head.toml")
    scenario.set("flow.boundary[1].head", 3.0)  # the left's: still water, which summary warns of
    sim = hydrodda.Simulation(scenario)
    sim.solve()
    handler = CallOnALine("still water", lambda: sim.fluid)
    logger = logging.getLogger("hydrodda")
    logger.addHandler(handler)
    try:
        sim.summary  # noqa: B018
    finally:
        logger.removeHandler(handler)
    assert handler.raised and all("fluid: this Simulation is in a call on this thread already" in r
                                  for r in handler.raised)
    assert "head" in sim.fluid  # not held after the refusal


BLAS_FLAG = """
import sys
if sys.argv[1] == "numpy":
    import numpy  # noqa: F401 — loads OpenBLAS before the module does
import hydrodda
print(hydrodda._hydrodda._blas_is_thread_safe())
"""


def test_blas_from_two_threads_only_where_its_buffers_are_guarded():
    """OpenBLAS hands out its work buffers without a lock; the module puts one around them, which
    OpenBLAS's own calls reach only where the module loaded it. NumPy imported first loads it
    without: the module must not then call BLAS from two threads (it said it could)."""
    said = {}
    for first in ("numpy", "hydrodda"):
        child = subprocess.run([sys.executable, "-c", BLAS_FLAG, first], capture_output=True, text=True,
                               env=os.environ, timeout=60)
        assert child.returncode == 0, child.stderr
        said[first] = child.stdout.strip()
    assert said == {"numpy": "False", "hydrodda": "True"}


def fields_of(sim):
    """Every field a Simulation gives, as {group: {name: array}}."""
    groups = {"blocks": sim.blocks, "contacts": sim.contacts}
    if sim.kind == "coupled":
        groups["fluid"] = sim.fluid
    return groups


def assert_same(one, two, name):
    """The same value bit for bit: an array, or a list of them (the blocks' vertices)."""
    if isinstance(one, (list, tuple)):
        assert len(one) == len(two), name
        for k, (a, b) in enumerate(zip(one, two)):
            assert_same(a, b, f"{name}[{k}]")
    else:
        np.testing.assert_array_equal(one, two, err_msg=name)


def test_a_simulation_gives_the_same_fields_on_one_thread_and_on_two():
    """Simulation(threads=) as run(threads=): a coupled model on the fine mesh of the threads
    test (every loop of the flow side shared between threads), one pass, and the brick wall,
    sixty steps, each built and stepped on one thread and on two, end with the same fields, bit
    for bit, and the pass measures the same."""
    flexure = hydrodda.Scenario.load(SOURCE_DIR / "tests/cli/scenarios/threads_flexure.toml")
    wall = hydrodda.Scenario.load(VERIFICATION / "brick_wall_determinism.toml")
    wall.set("mechanics.steps", 60)
    ends = {}
    for threads in (1, 2):
        coupled = hydrodda.Simulation(flexure, threads=threads)
        report = coupled.run_pass()
        mechanics = hydrodda.Simulation(wall, threads=threads)
        assert mechanics.step(60) == 60
        ends[threads] = (report, fields_of(coupled), fields_of(mechanics))
    (report_1, coupled_1, mechanics_1), (report_2, coupled_2, mechanics_2) = ends[1], ends[2]
    assert report_1 == report_2
    for one, two in ((coupled_1, coupled_2), (mechanics_1, mechanics_2)):
        assert one.keys() == two.keys()
        for group in one:
            assert one[group].keys() == two[group].keys()
            for name in one[group]:
                assert_same(one[group][name], two[group][name], f"{group}.{name}")


def test_a_simulation_refuses_a_bad_thread_count(monkeypatch):
    """What run(threads=) refuses, Simulation(threads=) refuses before building anything: 0,
    4097, 1.5, True; and a bad HYDRODDA_THREADS when threads= is not given."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "free_fall.toml")
    for threads in (0, 4097, 1.5, True):
        with pytest.raises(ValueError, match="threads: must be a whole number from 1 to 4096"):
            hydrodda.Simulation(scenario, threads=threads)
    monkeypatch.setenv("HYDRODDA_THREADS", "many")
    with pytest.raises(hydrodda.InputError, match="HYDRODDA_THREADS"):
        hydrodda.Simulation(scenario)
    assert hydrodda.Simulation(scenario, threads=1).step(1) == 1  # threads= is chosen over the variable
