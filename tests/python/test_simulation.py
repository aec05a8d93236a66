"""Models stepped from Python, their fields as NumPy arrays without files."""

import json

import numpy as np
import pytest

import hydrodda
from conftest import VERIFICATION


def test_flow_fields_are_the_exact_linear_head():
    """flow_linear_head.toml: h = 3 - x and q = (K, 0), K = k rho g / mu = 9.81e-6 m/s, which P1
    reproduces to round-off on any mesh (1e-9 relative)."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "flow_linear_head.toml")
    scenario.set("mesh.size", 0.25)
    sim = hydrodda.Simulation(scenario)
    assert sim.kind == "flow" and not sim.finished
    fluid = sim.fluid
    assert "head" not in fluid  # not solved yet
    sim.solve()
    assert sim.finished
    fluid = sim.fluid
    nodes, triangles = fluid["nodes"], fluid["triangles"]
    assert nodes.ndim == 2 and nodes.shape[1] == 2 and triangles.shape[1] == 3
    assert triangles.min() == 0 and triangles.max() == len(nodes) - 1
    assert fluid["head"].shape == fluid["pressure"].shape == (len(nodes),)
    assert fluid["flux"].shape == (len(triangles), 2) and fluid["permeability"].shape == (len(triangles),)
    np.testing.assert_allclose(fluid["head"], 3.0 - nodes[:, 0], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(fluid["flux"][:, 0], 9.81e-6, rtol=1e-9)
    np.testing.assert_allclose(fluid["flux"][:, 1], 0.0, atol=1e-9 * 9.81e-6)
    assert sim.summary["flow"]["boundaries"]["left"] == pytest.approx(-9.81e-6, rel=1e-9)
    with pytest.raises(RuntimeError, match="not for a flow simulation"):
        sim.step()


def test_mechanics_steps_are_free_fall():
    """free_fall.toml: d = g t^2 / 2 after n steps of 1e-3 s, exact to round-off (1e-9)."""
    sim = hydrodda.Simulation(hydrodda.Scenario.load(VERIFICATION / "free_fall.toml"))
    assert sim.step(10) == 10
    blocks = sim.blocks
    assert blocks["displacement"].shape == (1, 2) and blocks["stress"].shape == (1, 3)
    assert blocks["rotation"].shape == (1,) and blocks["area"] == pytest.approx([1.0])
    assert blocks["displacement"][0, 1] == pytest.approx(-0.5 * 9.81 * 0.01**2, rel=1e-9)
    polygon = blocks["polygons"][0]
    assert polygon.shape == (4, 2)
    assert polygon[:, 1].min() == pytest.approx(blocks["displacement"][0, 1], abs=1e-12)
    assert len(sim.contacts["state"]) == 0
    sim.step(5)
    assert sim.summary["iterations"] == 15
    with pytest.raises(RuntimeError, match="not for a mechanics simulation"):
        sim.run_pass()


def test_coupled_passes_reach_the_runs_results(in_tmp):
    """Passes stepped by hand end where hydrodda.run ends, bit for bit."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "coupled_hydrostatic_column.toml")
    result = hydrodda.run(scenario, "run")
    sim = hydrodda.Simulation(scenario)
    passes = []
    while not sim.finished:
        passes.append(sim.run_pass())
    assert len(passes) == result.iterations
    assert [p["head_change"] for p in passes] == result.history["head_change"].tolist()
    summary = sim.summary
    assert summary["blocks"] == result.summary["blocks"]
    assert summary["flow"] == result.summary["flow"]

    blocks = sim.blocks
    np.testing.assert_array_equal(blocks["displacement"], [b["displacement"] for b in result.summary["blocks"]])
    np.testing.assert_array_equal(blocks["stress"], [b["stress"] for b in result.summary["blocks"]])
    fluid = sim.fluid
    # No flow: the head is 3 m everywhere (both boundaries at 3 m).
    np.testing.assert_allclose(fluid["head"], 3.0, rtol=1e-12)
    assert fluid["porosity"].shape == fluid["permeability"].shape == (len(fluid["triangles"]),)
    assert ((fluid["porosity"] >= 0) & (fluid["porosity"] <= 1)).all()
    contacts = sim.contacts
    n = len(contacts["state"])
    assert n > 0 and all(len(contacts[k]) == n for k in contacts)
    assert set(contacts["state"]) <= {"open", "sliding", "locked"}
    assert contacts["block_i"].max() < len(blocks["area"]) and contacts["block_j"].max() < len(blocks["area"])
    # The stacked blocks press on each other: the closed contacts carry compression.
    closed = contacts["state"] != "open"
    assert closed.any() and (contacts["normal_force"][closed] > 0).all()
