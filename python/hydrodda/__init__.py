"""hydrodda from Python: scenarios, runs into run folders, and their results as NumPy arrays.

    import hydrodda
    scenario = hydrodda.Scenario.load("scenarios/paper/four_blocks.toml")
    scenario.set("flow.boundary[0].head", 30.0)
    result = hydrodda.run(scenario, "runs/four_blocks_30m")
    print(result.converged, result.summary["flow"]["boundaries"])

See docs/python.md for every call.
"""

import json
import numbers
import platform
import sys
from pathlib import Path


def _for_another_interpreter(error):
    """`error` (the extension or NumPy not found) saying which interpreter hydrodda is built for."""
    from ._built_for import INTERPRETER, VERSION
    message = (f"hydrodda is built for {INTERPRETER} (Python {VERSION}) with its NumPy; this is "
               f"{sys.executable} (Python {platform.python_version()}): {error} (docs/python.md, 'Getting it')")
    return type(error)(message, name=error.name, path=error.path)


try:
    from ._hydrodda import (  # noqa: F401
        Diagnostic,
        InputError,
        ProgressReport,
        RunFolderError,
        Scenario,
        ScenarioError,
        Simulation,
        __version__,
        _breach,
        _resume,
        _run,
    )
    from .run_folder import read_history
except ImportError as error:
    raise _for_another_interpreter(error) from error

__all__ = [
    "BreachResult", "Diagnostic", "InputError", "ProgressReport", "RunFolderError", "RunResult", "Scenario",
    "ScenarioError", "Simulation", "__version__", "breach", "read_history", "resume", "run",
]


class RunResult:
    """What a run did: status ('finished', 'stopped', 'interrupted', 'no equilibrium' or 'failed'),
    converged, iterations, message, summary (summary.json as a dict; its last_held after 'no
    equilibrium') and folder; history reads the run
    folder's history.csv into a dict of NumPy arrays, one per column.

    The model's fields as the run ended, from memory (no file is read), as dicts of NumPy
    arrays like Simulation's: fluid (flow and coupled runs), blocks and contacts (mechanics and
    coupled runs), fractures (runs of a scenario with a [geometry] domain that measured them);
    None where the run has none."""

    def __init__(self, fields):
        self.status = fields["status"]
        self.converged = fields["converged"]
        self.iterations = fields["iterations"]
        self.message = fields["message"]
        self.summary = json.loads(fields["summary_json"])
        self.folder = Path(fields["folder"])
        model = fields["fields"]
        self.fluid = model.get("fluid")
        self.blocks = model.get("blocks")
        self.contacts = model.get("contacts")
        self.fractures = model.get("fractures")
        self._history = None

    @property
    def history(self):
        if self._history is None:
            self._history = read_history(self.folder)
        return self._history

    def __repr__(self):
        return (f"<RunResult {self.status}, converged={self.converged}, "
                f"iterations={self.iterations}, folder={str(self.folder)!r}>")


def _check_count(name, count, most=None):
    """Refuses what `hydrodda run --stop-after` and `--threads` refuse: a count starts at 1."""
    if count is None:
        return None
    if (isinstance(count, bool) or not isinstance(count, numbers.Integral) or count < 1
            or (most is not None and count > most)):
        limit = f"from 1 to {most}" if most is not None else ">= 1"
        raise ValueError(f"{name}: must be a whole number {limit}, got {count!r}")
    return int(count)


def run(scenario, folder=None, *, progress=None, overwrite=False, stop_after=None, threads=None):
    """Runs `scenario` into `folder` (default: the scenario's output.directory) as `hydrodda run`
    does, file for file. `progress(report)` is called after every DDA step, coupling pass or
    flow solve. A folder that holds files raises RunFolderError unless `overwrite`. Ctrl-C stops
    the run after its current step or pass, with the folder at the last finished one, and then
    raises KeyboardInterrupt; an exception in `progress` stops it likewise and is raised.
    `threads`: how many this run uses (default: HYDRODDA_THREADS, else every core the process
    may use); the results are the same on any number."""
    stop_after = _check_count("stop_after", stop_after)
    threads = _check_count("threads", threads, 4096)
    return RunResult(_run(scenario, None if folder is None else Path(folder), overwrite, stop_after, progress,
                          threads))


def resume(folder, *, progress=None, stop_after=None, threads=None):
    """Continues the coupled run in `folder` (stopped by stop_after or interrupted) after its last
    finished pass, as `hydrodda run --resume` does; `threads` as for run()."""
    stop_after = _check_count("stop_after", stop_after)
    threads = _check_count("threads", threads, 4096)
    return RunResult(_resume(Path(folder), stop_after, progress, threads))


class BreachResult:
    """Where a breach search ended (docs/breach.md): held (the largest load that held) and
    broken (the least that did not), either None; broken_status ('beyond limit', 'not
    converged', 'held, unsettled' under converged_only, 'not at rest', 'no equilibrium', 'failed');
    a step that held unsettled (blocks at rest, the loop swinging) holds unless converged_only;
    narrowed (the bracket reached the tolerance); unsettled_held (how many steps below the breach
    held unsettled) and worst_unsettled_spread (of those, the widest spread of a region's
    K_eff/K_m, a dict of spread, load and region, as breach.json gives it; None when none);
    verdict (the line `hydrodda breach` prints); folder; steps, one dict per step tried (index,
    load, kind, status, passes, message); summary (breach.json as a dict)."""

    def __init__(self, fields):
        self.held = fields["held"]
        self.broken = fields["broken"]
        self.broken_status = fields["broken_status"]
        self.narrowed = fields["narrowed"]
        self.interrupted = fields["interrupted"]
        self.unsettled_held = fields["unsettled_held"]
        self.verdict = fields["verdict"]
        self.folder = Path(fields["folder"])
        self.steps = fields["steps"]
        self.summary = json.loads((self.folder / "breach.json").read_text())
        self.worst_unsettled_spread = self.summary["worst_unsettled_spread"]

    def __repr__(self):
        return f"<BreachResult {self.verdict!r}>"


def breach(scenario, vary, start, stop, *, steps=10, tolerance=0.005, limit=None, folder=None, overwrite=False,
           threads=None, converged_only=False):
    """Raises the load `vary` (a key path, or a list of key paths that take the same value) of a
    coupled `scenario` from `start` towards `stop` in `steps` equal steps, each from the last
    state that held, then bisects the first step that did not hold until the bracket is within
    `tolerance` of the load, as `hydrodda breach` does, into `folder` (default: the scenario's
    output.directory + "-breach"). `limit`: (path, value), a summary.json value a state must keep
    at or below to hold. `converged_only`: only a step whose coupling loop converged holds, as
    `--converged-only` does (a 'held, unsettled' step is then the breach). Ctrl-C ends the search
    after its current pass and raises KeyboardInterrupt. Returns a BreachResult."""
    keys = [vary] if isinstance(vary, str) else list(vary)
    steps = _check_count("steps", steps)
    threads = _check_count("threads", threads, 4096)
    limit_path, limit_value = (None, None) if limit is None else (str(limit[0]), float(limit[1]))
    return BreachResult(_breach(scenario, keys, float(start), float(stop), steps, float(tolerance), limit_path,
                                limit_value, None if folder is None else Path(folder), overwrite, threads,
                                bool(converged_only)))
