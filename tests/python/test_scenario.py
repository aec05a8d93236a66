"""Scenarios from Python: reading, changing by key path, checking, errors as the program says them."""

import re

import pytest

import hydrodda
from conftest import BAD_SCENARIOS, VERIFICATION, run_program


def test_version_is_the_programs():
    code, out, _ = run_program("--version")
    assert code == 0
    assert hydrodda.__version__ in out
    assert re.fullmatch(r"\d+\.\d+\.\d+", hydrodda.__version__)


def test_load_reads_the_file_and_keeps_its_text():
    path = VERIFICATION / "flow_layers_series.toml"
    scenario = hydrodda.Scenario.load(path)
    assert scenario.kind == "flow"
    assert scenario.title == "Flow verification: three layers in series, contrast 1e6"
    assert scenario.to_toml() == path.read_text()
    assert scenario.check() == []


def test_kinds():
    assert hydrodda.Scenario.load(VERIFICATION / "free_fall.toml").kind == "mechanics"
    assert hydrodda.Scenario.load(VERIFICATION / "coupled_hydrostatic_column.toml").kind == "coupled"


def test_from_toml_names_the_text_in_messages():
    text = (VERIFICATION / "free_fall.toml").read_text().replace("young = 1.0e10", "young = -1.0")
    with pytest.raises(hydrodda.ScenarioError) as error:
        hydrodda.Scenario.from_toml(text, name="mine.toml")
    [diagnostic] = error.value.diagnostics
    assert diagnostic.file == "mine.toml"
    assert diagnostic.key == "material.rock.young"
    assert diagnostic.line == text.splitlines().index("young = -1.0") + 1
    assert str(diagnostic) in str(error.value)


def test_load_errors_are_the_programs_lines():
    """Every line `hydrodda check` prints after "error: " is one diagnostic, in order."""
    for name in ["negative_young.toml", "misspelt_material_key.toml", "malformed_toml.toml", "flow_no_head.toml"]:
        path = BAD_SCENARIOS / name
        code, _, err = run_program("check", path)
        assert code == 2
        printed = [line[len("error: "):] for line in err.splitlines() if line.startswith("error: ")]
        with pytest.raises(hydrodda.ScenarioError) as error:
            hydrodda.Scenario.load(path)
        assert [str(d) for d in error.value.diagnostics] == printed, name
        assert isinstance(error.value, ValueError)


def test_missing_file():
    with pytest.raises(hydrodda.ScenarioError, match="cannot open the scenario file"):
        hydrodda.Scenario.load(VERIFICATION / "no_such_file.toml")


def test_check_returns_what_only_building_shows():
    path = BAD_SCENARIOS / "fixed_point_in_no_block.toml"
    scenario = hydrodda.Scenario.load(path)  # reads fine: the blocks show it
    code, _, err = run_program("check", path)
    assert code == 2
    printed = [line[len("error: "):] for line in err.splitlines() if line.startswith("error: ")]
    diagnostics = scenario.check()
    assert printed and [str(d) for d in diagnostics] == printed
    assert all(d.file == str(path) for d in diagnostics)


def test_set_uses_the_sweeps_key_paths():
    scenario = hydrodda.Scenario.load(VERIFICATION / "flow_layers_series.toml")
    original = scenario.to_toml()
    changed = scenario.copy()
    changed.set("flow.boundary[0].head", 30.0)
    changed.set("flow.fluid.viscosity", 2e-3)
    assert scenario.to_toml() == original  # the copy is independent
    text = changed.to_toml()
    assert re.search(r"head = 30\.0\b", text)
    assert re.search(r"viscosity = 0\.002\b", text)
    # Read back, the values are the ones set.
    again = hydrodda.Scenario.from_toml(text)
    assert again.to_toml() == text


def test_set_matches_sweep_overrides(in_tmp):
    """The same text as the program's sweep writes for its case of --set on the same key."""
    path = VERIFICATION / "flow_layers_series.toml"
    scenario = hydrodda.Scenario.load(path)
    scenario.set("flow.boundary[0].head", 2.5)
    # The sweep also titles each case with its values (flow.boundary[0] is named "left").
    scenario.set("title", scenario.title + " — head at left = 2.5 m")
    code, _, err = run_program("sweep", path, "--set", "flow.boundary[0].head=2.5", "--jobs", "1", "-o", "sweep",
                               cwd=in_tmp)
    assert code == 0, err
    assert (in_tmp / "sweep/case_000/scenario.toml").read_text() == scenario.to_toml()


def test_set_errors_leave_the_scenario_unchanged():
    scenario = hydrodda.Scenario.load(VERIFICATION / "flow_layers_series.toml")
    before = scenario.to_toml()
    with pytest.raises(hydrodda.ScenarioError) as error:
        scenario.set("flow.boundary[7].head", 1.0)
    assert "flow.boundary[7].head" in str(error.value)
    with pytest.raises(hydrodda.ScenarioError) as error:
        scenario.set("flow.fluid.viscosity", -1.0)
    assert [d.key for d in error.value.diagnostics] == ["flow.fluid.viscosity"]
    with pytest.raises(TypeError):
        scenario.set("flow.fluid.viscosity", object())
    assert scenario.to_toml() == before


def test_set_values_of_every_type():
    scenario = hydrodda.Scenario.load(VERIFICATION / "free_fall.toml")
    scenario.set("mechanics.gravity", [0.0, -10.0])
    scenario.set("mechanics.contact", "penalty")
    scenario.set("mechanics.time_step", 2)  # an integer where a float goes
    scenario.set("geometry.block[0].fixed", False)
    text = scenario.to_toml()
    assert re.search(r"gravity = \[\s*0\.0,\s*-10\.0\s*\]", text)
    assert re.search(r"contact = ['\"]penalty['\"]", text)
    assert re.search(r"time_step = 2\b", text)
    assert re.search(r"fixed = false\b", text)
    with pytest.raises(hydrodda.ScenarioError) as error:
        scenario.set("mechanics.contact", 3)
    assert [d.key for d in error.value.diagnostics] == ["mechanics.contact"]


def test_a_list_that_contains_itself_is_refused():
    scenario = hydrodda.Scenario.load(VERIFICATION / "free_fall.toml")
    gravity = [0.0, -9.81]
    gravity.append(gravity)
    with pytest.raises(ValueError, match=r"mechanics.gravity: a list that contains itself"):
        scenario.set("mechanics.gravity", gravity)
    assert scenario.to_toml() == (VERIFICATION / "free_fall.toml").read_text()  # unchanged


def test_lists_nested_deeper_than_any_scenario_value_are_refused():
    """200,000 levels overflowed the stack of the conversion to TOML."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "free_fall.toml")
    deep = [0.0]
    for _ in range(200_000):
        deep = [deep]
    with pytest.raises(ValueError, match=r"mechanics.gravity: lists nested more than 32 deep"):
        scenario.set("mechanics.gravity", deep)
    # A list that holds the same list twice (not itself) is a value like any other.
    point = [0.0, -9.81]
    with pytest.raises(hydrodda.ScenarioError):
        scenario.set("mechanics.gravity", [point, point])
