"""hydrodda.breach: the breach search from Python, as `hydrodda breach` runs it."""

import json

import pytest

import hydrodda
from conftest import VERIFICATION, run_program

JACKING = VERIFICATION / "breach_hydraulic_jacking.toml"
MOUTHS = ["flow.boundary[0].head", "flow.boundary[1].head"]
# H* = rho_r h / rho_w = 2500 kg/m3 x 1 m / 1000 kg/m3 (force balance on the block).
JACKING_HEAD = 2.5


def test_the_search_brackets_the_jacking_head_as_the_program_does(tmp_path):
    scenario = hydrodda.Scenario.load(JACKING)
    result = hydrodda.breach(scenario, MOUTHS, 2.0, 3.0, steps=5, folder=tmp_path / "python", threads=1)
    # The model's threshold lies 0.09-0.16% above H* (coupled_hydraulic_jacking.toml).
    assert result.held <= JACKING_HEAD * 1.002
    assert result.broken >= JACKING_HEAD * 0.998
    assert result.broken - result.held <= 0.005 * result.broken
    assert result.narrowed and not result.interrupted
    assert result.steps[0]["status"] == "held" and result.steps[0]["load"] == 2.0
    assert result.summary["held"] == result.held

    code, out, err = run_program("breach", JACKING, "--vary", MOUTHS[0], "--vary", MOUTHS[1], "--from", "2",
                                 "--to", "3", "--steps", "5", "--threads", "1", "-o", tmp_path / "program")
    assert code == 0, out + err
    assert json.loads((tmp_path / "program" / "breach.json").read_text()) == result.summary
    assert (tmp_path / "program" / "breach.csv").read_text() == (tmp_path / "python" / "breach.csv").read_text()


def test_a_key_that_is_no_load_is_refused(tmp_path):
    scenario = hydrodda.Scenario.load(JACKING)
    with pytest.raises(ValueError, match="a loading path varies"):
        hydrodda.breach(scenario, "coupling.relaxation", 0.5, 1.0, folder=tmp_path / "out")
    with pytest.raises(ValueError, match="steps"):
        hydrodda.breach(scenario, MOUTHS, 2.0, 3.0, steps=0, folder=tmp_path / "out")
    assert not (tmp_path / "out" / "breach.csv").exists()


def test_converged_only_is_the_programs_flag_and_the_unsettled_count_is_breach_json(tmp_path):
    """converged_only=True searches as `hydrodda breach --converged-only` does, to the same files;
    the result's unsettled_held and worst_unsettled_spread are breach.json's. The jacked block's
    loop converges at every load that holds, so no step held unsettled: 0 and None."""
    scenario = hydrodda.Scenario.load(JACKING)
    result = hydrodda.breach(scenario, MOUTHS, 2.0, 3.0, steps=5, folder=tmp_path / "python", threads=1,
                             converged_only=True)
    assert result.summary["rule"] == "converged only"
    assert result.verdict.startswith("converged-only")
    assert result.held <= JACKING_HEAD * 1.002 and result.broken >= JACKING_HEAD * 0.998
    assert result.unsettled_held == result.summary["unsettled_held"] == 0
    assert result.worst_unsettled_spread is None and result.summary["worst_unsettled_spread"] is None

    code, out, err = run_program("breach", JACKING, "--vary", MOUTHS[0], "--vary", MOUTHS[1], "--from", "2",
                                 "--to", "3", "--steps", "5", "--threads", "1", "--converged-only",
                                 "-o", tmp_path / "program")
    assert code == 0, out + err
    assert json.loads((tmp_path / "program" / "breach.json").read_text()) == result.summary
