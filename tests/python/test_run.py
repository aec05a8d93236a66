"""Runs from Python: the same run folder as the program's, file for file; the result's fields;
the program's errors as exceptions."""

import importlib.util
import json

import numpy as np
import pytest

import hydrodda
from conftest import SOURCE_DIR, VERIFICATION, run_program

# The comparison of scripts/compare_run_folders.py: every file byte for byte, summary.json
# without its timings, checkpoint.bin with its timings zeroed.
_spec = importlib.util.spec_from_file_location("compare_run_folders", SOURCE_DIR / "scripts/compare_run_folders.py")
compare_run_folders = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(compare_run_folders)


def expect_same_folders(program_folder, python_folder):
    problems = []
    files = compare_run_folders.compare_folders(program_folder, python_folder, "python", problems)
    assert problems == []
    assert files > 0
    return files


def write_scenario(folder, source, changes, name):
    """`source` with `changes` (key path → value) applied, written to folder/name; its path."""
    scenario = hydrodda.Scenario.load(source)
    for key, value in changes.items():
        scenario.set(key, value)
    (folder / name).write_text(scenario.to_toml())
    return name


def without_timings(summary):
    return {k: v for k, v in summary.items() if k != "timings"}


def run_both(in_tmp, scenario_file, **options):
    """The scenario run by the program into prog/ and by Python into py/."""
    code, _, err = run_program("run", scenario_file, "-o", "prog", cwd=in_tmp)
    assert code == 0, err
    reports = []
    result = hydrodda.run(hydrodda.Scenario.load(scenario_file), "py", progress=reports.append, **options)
    return result, reports


def test_flow_only_run_is_the_programs(in_tmp):
    name = write_scenario(in_tmp, VERIFICATION / "flow_layers_series.toml", {"mesh.size": 0.1}, "flow.toml")
    result, reports = run_both(in_tmp, name)
    expect_same_folders(in_tmp / "prog", in_tmp / "py")
    assert (result.status, result.converged, result.iterations, result.message) == ("finished", True, 1, "")
    assert result.folder == in_tmp / "py" or result.folder.resolve() == (in_tmp / "py").resolve()
    assert without_timings(result.summary) == without_timings(json.loads((in_tmp / "prog/summary.json").read_text()))
    assert [r.kind for r in reports] == ["flow_solve"]
    assert abs(reports[0].balance_error) < 1e-8


def test_transient_flow_run_is_the_programs(in_tmp):
    """A transient flow-only run from Python writes the program's folder (probes.csv,
    history.csv, fluid.pvd at its output times), reporting each step."""
    name = write_scenario(in_tmp, VERIFICATION / "transient_steady_limit.toml", {"mesh.size": 1.0}, "transient.toml")
    result, reports = run_both(in_tmp, name)
    expect_same_folders(in_tmp / "prog", in_tmp / "py")
    assert (result.status, result.converged) == ("finished", True)
    assert result.summary["time"] == 4000.0
    assert len(reports) == result.iterations and result.iterations > 1
    assert (in_tmp / "py" / "probes.csv").read_text().startswith("time,name,head,pressure\n")


def test_a_transient_run_stopped_and_resumed_is_the_programs(in_tmp):
    """A transient run stopped by its progress callback after 300 steps keeps checkpoint.bin of
    its last finished step; hydrodda.resume continues it to the folder the program writes in one
    go, file for file."""
    name = write_scenario(in_tmp, VERIFICATION / "transient_diffusion_1d.toml",
                          {"mesh.size": 0.5, "output.figures": []}, "strip.toml")
    name = in_tmp / name  # summary.json's "scenario": a resumed run names the file by its absolute path
    code, _, err = run_program("run", name, "-o", "prog", cwd=in_tmp)
    assert code == 0, err

    class Enough(Exception):
        pass

    def progress(report):
        if report.count == 300:
            raise Enough()

    with pytest.raises(Enough):
        hydrodda.run(hydrodda.Scenario.load(name), "py", progress=progress)
    stopped = json.loads((in_tmp / "py" / "summary.json").read_text())
    assert (stopped["status"], stopped["iterations"]) == ("interrupted", 300)
    result = hydrodda.resume("py")
    assert (result.status, result.converged, result.iterations) == ("finished", True, 1021)
    expect_same_folders(in_tmp / "prog", in_tmp / "py")


def test_mechanics_only_run_is_the_programs(in_tmp):
    end_time = 0.05
    name = write_scenario(in_tmp, VERIFICATION / "free_fall.toml", {"mechanics.end_time": end_time}, "fall.toml")
    result, reports = run_both(in_tmp, name)
    expect_same_folders(in_tmp / "prog", in_tmp / "py")
    assert (result.status, result.converged, result.iterations) == ("finished", True, 50)
    # Free fall from rest: d = g t^2 / 2 = 0.0122625 m at t = 0.05 s; the step is exact for a
    # constant acceleration, to round-off (1e-9 relative).
    dy = result.summary["measure"]["centre"]["displacement"][1]
    assert dy == pytest.approx(-0.5 * 9.81 * end_time**2, rel=1e-9)
    assert len(reports) == 50 and [r.count for r in reports] == list(range(1, 51))
    assert all(r.kind == "mechanics_step" for r in reports)
    history = result.history
    assert list(history)[:2] == ["step", "time"]
    assert history["time"].shape == (50,) and history["time"].dtype == np.float64
    assert history["time"][-1] == pytest.approx(end_time, rel=1e-12)
    np.testing.assert_array_equal(history["step"], np.arange(1, 51))
    assert [r.time for r in reports] == pytest.approx(history["time"].tolist(), rel=1e-15)


def test_coupled_run_is_the_programs(in_tmp):
    name = write_scenario(in_tmp, VERIFICATION / "coupled_hydrostatic_column.toml", {}, "column.toml")
    result, reports = run_both(in_tmp, name)
    files = expect_same_folders(in_tmp / "prog", in_tmp / "py")
    assert files >= 10  # VTU series, history, checkpoint, scenario copy, summary
    assert result.status == "finished" and result.converged
    assert result.iterations == result.summary["iterations"] == len(reports)
    assert all(r.kind == "coupling_pass" for r in reports)
    history = result.history
    np.testing.assert_array_equal(history["iteration"], np.arange(1, result.iterations + 1))
    assert [r.head_change for r in reports] == history["head_change"].tolist()
    assert [r.displacement_change for r in reports] == history["displacement_change"].tolist()


def test_a_folder_with_files_is_refused_as_by_the_program(in_tmp):
    name = write_scenario(in_tmp, VERIFICATION / "flow_layers_series.toml", {"mesh.size": 0.1}, "flow.toml")
    (in_tmp / "full").mkdir()
    (in_tmp / "full/summary.json").write_text("mine")
    code, _, err = run_program("run", name, "-o", "full", cwd=in_tmp)
    assert code == 2
    with pytest.raises(hydrodda.RunFolderError) as error:
        hydrodda.run(hydrodda.Scenario.load(name), "full")
    assert str(error.value) in err
    assert (in_tmp / "full/summary.json").read_text() == "mine"
    # With overwrite the run replaces it.
    assert hydrodda.run(hydrodda.Scenario.load(name), "full", overwrite=True).status == "finished"


def test_stop_after_on_a_flow_run_is_an_input_error(in_tmp):
    name = write_scenario(in_tmp, VERIFICATION / "flow_layers_series.toml", {"mesh.size": 0.1}, "flow.toml")
    with pytest.raises(hydrodda.InputError, match="stop"):
        hydrodda.run(hydrodda.Scenario.load(name), "stopped", stop_after=1)
    assert not (in_tmp / "stopped").exists()


def test_stop_after_counts_from_one_as_the_programs(in_tmp):
    """`--stop-after 0` is refused by the program; so is stop_after=0, before anything runs."""
    name = write_scenario(in_tmp, VERIFICATION / "coupled_hydrostatic_column.toml", {}, "column.toml")
    code, _, err = run_program("run", name, "-o", "prog", "--stop-after", "0", cwd=in_tmp)
    assert code != 0 and "must be a whole number >= 1, got 0" in err
    for stop_after in (0, -1):
        with pytest.raises(ValueError, match=f"stop_after: must be a whole number >= 1, got {stop_after}"):
            hydrodda.run(hydrodda.Scenario.load(name), "py", stop_after=stop_after)
        with pytest.raises(ValueError, match="stop_after: must be a whole number >= 1"):
            hydrodda.resume("py", stop_after=stop_after)
    assert not (in_tmp / "py").exists()


def test_a_model_error_raises_and_leaves_no_folder(in_tmp):
    scenario = hydrodda.Scenario.load(SOURCE_DIR / "tests/cli/bad_scenarios/fixed_point_in_no_block.toml")
    with pytest.raises(hydrodda.ScenarioError) as error:
        hydrodda.run(scenario, "bad")
    assert [str(d) for d in error.value.diagnostics] == [str(d) for d in scenario.check()]
    assert not (in_tmp / "bad").exists()


def test_stop_after_then_resume_is_the_programs(in_tmp):
    name = write_scenario(in_tmp, VERIFICATION / "coupled_hydrostatic_column.toml", {}, "column.toml")
    for arguments in (["run", name, "-o", "prog", "--stop-after", "1"], ["run", "--resume", "prog"]):
        code, _, err = run_program(*arguments, cwd=in_tmp)
        assert code == 0, err
    whole = hydrodda.run(hydrodda.Scenario.load(name), "whole")
    stopped = hydrodda.run(hydrodda.Scenario.load(name), "py", stop_after=1)
    assert (stopped.status, stopped.iterations, stopped.converged) == ("stopped", 1, False)
    resumed = hydrodda.resume("py")
    assert (resumed.status, resumed.iterations, resumed.converged) == ("finished", whole.iterations, True)
    expect_same_folders(in_tmp / "prog", in_tmp / "py")


def test_an_error_in_the_progress_callback_stops_the_run_and_is_raised(in_tmp):
    name = write_scenario(in_tmp, VERIFICATION / "coupled_hydrostatic_column.toml", {}, "column.toml")

    def progress(report):
        raise RuntimeError(f"stop at pass {report.count}")

    with pytest.raises(RuntimeError, match="stop at pass 1"):
        hydrodda.run(hydrodda.Scenario.load(name), "py", progress=progress)
    summary = json.loads((in_tmp / "py/summary.json").read_text())
    assert summary["iterations"] == 1 and not summary["converged"]


def test_threads_change_no_result_and_bad_counts_are_refused(in_tmp, monkeypatch):
    """threads= as `--threads`: the same run folder on one thread and on three; 0, 4097, 1.5 and
    True raise ValueError before anything runs; a bad HYDRODDA_THREADS raises InputError naming it."""
    name = write_scenario(in_tmp, VERIFICATION / "coupled_hydrostatic_column.toml", {}, "column.toml")
    for threads, folder in ((1, "one"), (3, "three")):
        assert hydrodda.run(hydrodda.Scenario.load(name), folder, threads=threads).status == "finished"
    expect_same_folders(in_tmp / "one", in_tmp / "three")
    for threads in (0, 4097, 1.5, True):
        with pytest.raises(ValueError, match="threads: must be a whole number from 1 to 4096"):
            hydrodda.run(hydrodda.Scenario.load(name), "bad", threads=threads)
        with pytest.raises(ValueError, match="threads: must be a whole number from 1 to 4096"):
            hydrodda.resume("one", threads=threads)
    monkeypatch.setenv("HYDRODDA_THREADS", "many")
    with pytest.raises(hydrodda.InputError, match="HYDRODDA_THREADS must be a whole number from 1 to 4096, got 'many'"):
        hydrodda.run(hydrodda.Scenario.load(name), "bad")
    assert not (in_tmp / "bad").exists()
    # The call's own count comes first.
    assert hydrodda.run(hydrodda.Scenario.load(name), "two", threads=2).status == "finished"
