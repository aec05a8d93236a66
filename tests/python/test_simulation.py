"""Models stepped from Python, their fields as NumPy arrays without files."""

import csv
import json

import numpy as np
import pytest

import hydrodda
from conftest import SOURCE_DIR, VERIFICATION, run_program


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
    # The column settles at full steps: every pass's last step ran at the file's 0.05 s, and
    # no step of a pass was longer than that.
    assert all(p["full_time_step"] and 0 < p["shortest_time_step"] <= 0.05 for p in passes)
    assert passes[-1]["converged"]
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


def test_run_result_keeps_the_models_last_fields(in_tmp):
    """hydrodda.run's result holds the fields of its model's last state, from memory: the same
    arrays a Simulation stepped to the same pass shows, bit for bit, and the fractures as
    fractures.csv's last rows give them."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "coupled_hydrostatic_column.toml")
    result = hydrodda.run(scenario, "run")
    sim = hydrodda.Simulation(scenario)
    while not sim.finished:
        sim.run_pass()
    for name in ("nodes", "triangles", "head", "pressure", "flux", "permeability", "porosity"):
        np.testing.assert_array_equal(result.fluid[name], sim.fluid[name])
    for name in ("displacement", "rotation", "stress", "area"):
        np.testing.assert_array_equal(result.blocks[name], sim.blocks[name])
    np.testing.assert_array_equal(result.contacts["normal_force"], sim.contacts["normal_force"])

    rows = np.genfromtxt("run/fractures.csv", delimiter=",", names=True, dtype=None, encoding=None)
    last = rows[rows["step"] == result.iterations]
    fractures = result.fractures
    assert len(fractures["id"]) == len(last) > 0
    np.testing.assert_array_equal(fractures["id"], last["fracture"])
    # fractures.csv prints 10 significant digits.
    np.testing.assert_allclose(fractures["length"], last["length"], rtol=1e-9)
    np.testing.assert_allclose(fractures["mean_aperture"], last["mean_aperture"], rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(fractures["flow"], last["flow"], rtol=1e-9, atol=1e-20)
    # The Simulation measures the same fractures.
    np.testing.assert_array_equal(sim.fractures["mean_aperture"], fractures["mean_aperture"])
    np.testing.assert_array_equal(sim.fractures["flow"], fractures["flow"])


def test_run_result_fields_by_kind_of_run(in_tmp):
    """A flow-only run has a fluid and no blocks; a mechanics-only run of listed blocks has
    blocks and contacts, and no fractures (it has no traces)."""
    flow = hydrodda.run(hydrodda.Scenario.load(VERIFICATION / "flow_linear_head.toml"), "flow")
    assert flow.blocks is None and flow.contacts is None and flow.fractures is None
    np.testing.assert_allclose(flow.fluid["head"], 3.0 - flow.fluid["nodes"][:, 0], rtol=1e-9, atol=1e-9)
    fall = hydrodda.run(hydrodda.Scenario.load(VERIFICATION / "free_fall.toml"), "fall")
    assert fall.fluid is None and fall.fractures is None
    np.testing.assert_array_equal(fall.blocks["displacement"], [b["displacement"] for b in fall.summary["blocks"]])


def test_a_loading_path_lifts_the_block_and_lets_it_down():
    """coupled_hydraulic_jacking.toml: a 1 m block over an open fracture lifts when the head in
    the fracture passes H* = rho_r h / rho_w = 2.5 m (overpressure), and rests on the lower
    block below it. With passes of fixed steps (coupling.settle = false: above H* there is no
    equilibrium, and passes that step on towards rest throw the block off), one Simulation: the
    mouths at 2.6 m for two passes lift it by millimetres;
    lowered to 2.0 m it comes back down and converges resting where a Simulation held at 2.0 m
    from the start rests, within 1e-6 m (the DDA's penetration tolerance, 1e-4 of the allowed
    step displacement of 1e-2 m, which is how far the resting contact's overlap may differ)."""
    held = hydrodda.Scenario.load(VERIFICATION / "coupled_hydraulic_jacking.toml")
    held.set("flow.boundary[0].head", 2.0)
    held.set("flow.boundary[1].head", 2.0)
    held.set("coupling.settle", False)
    direct = hydrodda.Simulation(held)
    while not direct.finished:
        direct.run_pass()
    rest = direct.summary["measure"]["lift"]["displacement"][1]
    assert -6e-5 < rest < 0.0  # down by the initial aperture, 5e-5 m, and the contact's overlap

    sim = hydrodda.Simulation(held)
    sim.set("flow.boundary[0].head", 2.6)
    sim.set("flow.boundary[1].head", 2.6)
    assert sim.scenario.to_toml().count("head = 2.6") == 2
    sim.run_pass()
    sim.run_pass()
    assert sim.summary["measure"]["lift"]["displacement"][1] > 4e-3
    # The flow solved in those passes has the new heads on the mouths.
    nodes, head = sim.fluid["nodes"], sim.fluid["head"]
    mouth = (np.abs(nodes[:, 0]) < 1e-12) & (np.abs(nodes[:, 1] - 1.0) < 0.004)
    assert mouth.any()
    np.testing.assert_allclose(head[mouth], 2.6, rtol=1e-12)

    sim.set("flow.boundary[0].head", 2.0)
    sim.set("flow.boundary[1].head", 2.0)
    assert not sim.finished
    for _ in range(8):
        if sim.run_pass()["converged"]:
            break
    assert sim.finished
    assert sim.summary["measure"]["lift"]["displacement"][1] == pytest.approx(rest, abs=1e-6)


def test_a_loading_path_changes_the_traction():
    """elastic_block_plane_strain.toml: a free block on a fixed base under a top traction p has
    sigma_yy = -p in equilibrium (the stress is uniform in a DDA block: 1e-6 relative after
    200 steps). Stepped to equilibrium at 1 MPa, then the traction set to 3 MPa and stepped
    again: sigma_yy = -3 MPa."""
    sim = hydrodda.Simulation(hydrodda.Scenario.load(VERIFICATION / "elastic_block_plane_strain.toml"))
    sim.step(100)
    assert sim.blocks["stress"][1, 1] == pytest.approx(-1.0e6, rel=1e-6)
    sim.set("mechanics.traction[0].normal", -3.0e6)
    sim.step(100)
    assert sim.blocks["stress"][1, 1] == pytest.approx(-3.0e6, rel=1e-6)


def test_a_loading_path_may_be_a_time_table():
    """The same block with its traction set to a table (docs/scenario.md, "Loads over time"):
    -1 MPa at t = 0 raised to -3 MPa at t = 0.5 s of DDA time and held after it. A mechanics
    Simulation reads it at each step's end as a run does, so at t = 2 s (200 steps of 0.01 s,
    150 of them at the held value) sigma_yy = -3 MPa (1e-6 relative, as above)."""
    sim = hydrodda.Simulation(hydrodda.Scenario.load(VERIFICATION / "elastic_block_plane_strain.toml"))
    sim.set("mechanics.traction[0].normal", [[0.0, -1.0e6], [0.5, -3.0e6]])
    sim.step(200)
    assert sim.blocks["stress"][1, 1] == pytest.approx(-3.0e6, rel=1e-6)
    with pytest.raises(hydrodda.ScenarioError, match="must increase"):
        sim.set("mechanics.traction[0].normal", [[1.0, -1.0e6], [0.5, -3.0e6]])


def test_set_refuses_what_is_not_a_load():
    """Only boundary values and tractions change between passes: the mesh, the blocks and the
    kind of a condition are fixed when the Simulation is built."""
    sim = hydrodda.Simulation(hydrodda.Scenario.load(VERIFICATION / "coupled_hydraulic_jacking.toml"))
    with pytest.raises(ValueError, match="not 'mesh.size'"):
        sim.set("mesh.size", 0.1)
    with pytest.raises(hydrodda.ScenarioError):
        sim.set("flow.boundary[2].pressure", 0.0)   # a head boundary given a pressure as well
    with pytest.raises(hydrodda.ScenarioError):
        sim.set("flow.boundary[7].head", 1.0)       # no such condition
    before = sim.scenario.to_toml()
    assert "head = 2.4" in before                   # nothing changed by the refusals


def test_a_flow_simulation_solves_again_with_a_new_head():
    """flow_linear_head.toml (x from 0 to 2): h = 3 - x; with the left head set to 5 m, the
    next solve gives h = 5 - 2x, exact in P1 (1e-9)."""
    sim = hydrodda.Simulation(hydrodda.Scenario.load(VERIFICATION / "flow_linear_head.toml"))
    sim.solve()
    sim.set("flow.boundary[0].head", 5.0)
    assert not sim.finished and "head" not in sim.fluid
    sim.solve()
    x = sim.fluid["nodes"][:, 0]
    np.testing.assert_allclose(sim.fluid["head"], 5.0 - 2.0 * x, rtol=1e-9, atol=1e-9)


def test_a_simulation_refuses_to_refine_tips_it_cannot_mesh_again():
    """mesh.refine_tips runs again on a refined mesh: hydrodda.run does it, a Simulation stepped
    by hand keeps its one mesh and says so rather than ignore the key."""
    scenario = hydrodda.Scenario.load(VERIFICATION.parent / "paper" / "symmetric_flexure_20m.toml")
    scenario.set("flow.permeability_law", "cubic")
    scenario.set("mesh.refine_tips", True)
    with pytest.raises(ValueError, match="mesh.refine_tips"):
        hydrodda.Simulation(scenario)


def transient_strip():
    """The 1D diffusion strip on a coarse mesh, no figures: 1,021 steps, outputs at 20, 100, 300
    and 1000 s."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "transient_diffusion_1d.toml")
    scenario.set("mesh.size", 0.5)
    scenario.set("output.figures", [])
    return scenario


def probes_csv_rows(folder):
    lines = (folder / "probes.csv").read_text().splitlines()
    assert lines[0] == "time,name,head,pressure"
    return [line.split(",") for line in lines[1:]]


def as_csv(row):
    """A probes row as the program writes it: numbers with 17 significant digits."""
    time, name, head, pressure = row
    return ["%.17g" % time, name, "%.17g" % head, "%.17g" % pressure]


def test_a_transient_simulation_stepped_to_the_end_gives_the_programs_probes_to_the_last_digit(in_tmp):
    """Stepped one time step at a time, then by advance_to over the output times, a transient
    Simulation reads at every step the probes.csv rows of the program's run of the same
    scenario, digit for digit (the same steps on the same heads: an exact identity), and its
    fluid at the end is the run's."""
    scenario = transient_strip()
    (in_tmp / "strip.toml").write_text(scenario.to_toml())
    code, _, err = run_program("run", "strip.toml", "-o", "prog", "--threads", "1", cwd=in_tmp)
    assert code == 0, err
    expected = probes_csv_rows(in_tmp / "prog")

    sim = hydrodda.Simulation(scenario, threads=1)
    assert (sim.kind, sim.time, sim.finished) == ("transient", 0.0, False)
    rows = [as_csv(r) for r in sim.probes]  # t = 0
    while not sim.finished:
        assert sim.step() == 1
        rows.extend(as_csv(r) for r in sim.probes)
    assert sim.step() == 0  # nothing past end_time
    assert sim.time == 1000.0 and len(sim.step_times) == 1021
    assert rows == expected
    summary = sim.summary
    assert (summary["converged"], summary["time"], summary["iterations"]) == (True, 1000.0, 1021)
    program_summary = json.loads((in_tmp / "prog" / "summary.json").read_text())
    assert summary["flow"] == program_summary["flow"]

    by_outputs = hydrodda.Simulation(scenario, threads=1)
    for t in (20.0, 100.0, 300.0, 1000.0):
        taken = by_outputs.advance_to(t)
        assert taken > 0 and by_outputs.time == t
        at_t = [as_csv(r) for r in by_outputs.probes]
        assert at_t == [r for r in expected if float(r[0]) == t]
    assert by_outputs.finished
    assert np.array_equal(by_outputs.fluid["head"], sim.fluid["head"])


def test_a_transient_simulation_refuses_times_no_step_ends_on_and_setting_a_boundary():
    sim = hydrodda.Simulation(transient_strip(), threads=1)
    with pytest.raises(ValueError, match="no step ends there"):
        sim.advance_to(20.5)  # steps of 1 s after 20 s (max_time_step)
    assert sim.advance_to(20.0) > 0
    with pytest.raises(ValueError, match="at t = 20 s already"):
        sim.advance_to(10.0)
    assert sim.advance_to(20.0) == 0
    with pytest.raises(ValueError, match="transient simulation takes its boundary values"):
        sim.set("flow.boundary[0].head", 12.0)
    with pytest.raises(Exception, match="not for a transient simulation"):
        sim.solve()


def test_the_time_and_probes_are_for_a_transient_simulation_alone():
    sim = hydrodda.Simulation(hydrodda.Scenario.load(VERIFICATION / "flow_linear_head.toml"))
    with pytest.raises(Exception, match="not for a flow simulation"):
        sim.time
    with pytest.raises(Exception, match="not for a flow simulation"):
        sim.advance_to(1.0)


@pytest.mark.parametrize("name", ["flow_linear_head", "free_fall", "coupled_hydrostatic_column"])
def test_summary_says_converged_as_the_runs_summary_does(in_tmp, name):
    """A finished model's summary says converged, as summary.json of its run does; one not yet
    finished says it did not."""
    scenario = hydrodda.Scenario.load(VERIFICATION / f"{name}.toml")
    if name == "free_fall":
        scenario.set("mechanics.end_time", 0.005)  # 5 steps
    sim = hydrodda.Simulation(scenario)
    advance = {"flow": sim.solve, "mechanics": sim.step, "coupled": sim.run_pass}[sim.kind]
    advance()
    if not sim.finished:
        assert sim.summary["converged"] is False
    while not sim.finished:
        advance()
    result = hydrodda.run(scenario, "run")
    assert result.converged and result.summary["converged"] is True
    assert sim.summary["converged"] is True


def terzaghi_column():
    """Terzaghi's column of twenty blocks as shipped, no figures: 54 steps to 1.4e5 s, outputs at
    4,667, 9,333, 28,000 and 93,330 s."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "terzaghi_consolidation.toml")
    scenario.set("output.figures", [])
    return scenario


def test_a_coupled_transient_simulation_stepped_to_the_end_gives_the_programs_probes_to_the_last_digit(in_tmp):
    """Stepped one time step at a time, then by advance_to over the output times, a coupled
    transient Simulation reads at every step the probes.csv rows of the program's run of the same
    scenario, digit for digit (the same steps, cut and grown alike, on the same blocks and heads:
    an exact identity); its summary is the run's apart from the fractures, and its blocks and
    fluid at the end are the same either way."""
    scenario = terzaghi_column()
    (in_tmp / "column.toml").write_text(scenario.to_toml())
    code, _, err = run_program("run", "column.toml", "-o", "prog", "--threads", "1", cwd=in_tmp)
    assert code == 0, err
    expected = probes_csv_rows(in_tmp / "prog")

    sim = hydrodda.Simulation(scenario, threads=1)
    assert (sim.kind, sim.time, sim.finished) == ("coupled_transient", 0.0, False)
    rows = [as_csv(r) for r in sim.probes]  # t = 0
    while not sim.finished:
        assert sim.step() == 1
        rows.extend(as_csv(r) for r in sim.probes)
    assert sim.step() == 0  # nothing past end_time
    assert sim.time == 1.4e5
    assert rows == expected
    summary = sim.summary
    program_summary = json.loads((in_tmp / "prog" / "summary.json").read_text())
    for key in ("converged", "time", "iterations", "flow", "blocks", "measure"):
        assert summary.get(key) == program_summary.get(key), key

    by_outputs = hydrodda.Simulation(scenario, threads=1)
    for t in (4667.0, 9333.0, 28000.0, 93330.0, 1.4e5):
        taken = by_outputs.advance_to(t)
        assert taken > 0 and by_outputs.time == t
        assert [as_csv(r) for r in by_outputs.probes] == [r for r in expected if float(r[0]) == t]
    assert by_outputs.finished
    assert np.array_equal(by_outputs.fluid["head"], sim.fluid["head"])
    assert np.array_equal(by_outputs.blocks["displacement"], sim.blocks["displacement"])


def test_a_coupled_transient_simulation_refuses_times_no_step_surely_ends_on_passes_and_setting_a_boundary():
    sim = hydrodda.Simulation(terzaghi_column(), threads=1)
    with pytest.raises(ValueError, match="no step of a coupled transient simulation surely ends there"):
        sim.advance_to(100.0)
    # The first step of 50 s takes 13 iterations, more than a quarter of max_iterations: the
    # second keeps its length.
    assert sim.step(2) == 2 and sim.time == 100.0
    with pytest.raises(ValueError, match="at t = 100 s already"):
        sim.advance_to(50.0)
    with pytest.raises(ValueError, match="transient simulation takes its boundary values"):
        sim.set("flow.boundary[0].head", 12.0)
    with pytest.raises(Exception, match="not for a coupled_transient simulation"):
        sim.run_pass()


def test_a_coupled_transient_simulation_records_the_bonds_each_step_broke_as_the_run_does(in_tmp):
    """The crack of broken bonds under a rising pressure (tests/cli/scenarios/bonded_crack_transient.toml:
    4, 1, 1 and 13 bonds break in its four 1 s steps), stepped by hand: sim.broken_bonds holds,
    after each step, the program's fractures.csv bond rows up to that step, cell for cell (the
    same steps on the same blocks: an exact identity), and their count by step is history.csv's
    broken_bonds."""
    scenario = hydrodda.Scenario.load(SOURCE_DIR / "tests/cli/scenarios/bonded_crack_transient.toml")
    scenario.set("output.figures", [])
    (in_tmp / "crack.toml").write_text(scenario.to_toml())
    code, _, err = run_program("run", "crack.toml", "-o", "prog", "--threads", "1", cwd=in_tmp)
    assert code == 0, err
    with open(in_tmp / "prog" / "fractures.csv") as f:
        bond_rows = [r for r in csv.DictReader(f) if r["origin"] == "bond"]
    with open(in_tmp / "prog" / "history.csv") as f:
        broken_per_step = [int(r["broken_bonds"]) for r in csv.DictReader(f)][1:]  # the row of t = 0 first
    assert broken_per_step == [4, 1, 1, 13]

    sim = hydrodda.Simulation(scenario, threads=1)
    assert len(sim.broken_bonds["step"]) == 0
    taken = 0
    while not sim.finished:
        assert sim.step() == 1
        taken += 1
        record = sim.broken_bonds
        expected = [r for r in bond_rows if int(r["step"]) <= taken]
        assert len(record["step"]) == len(expected) == sum(broken_per_step[:taken])
        for i, row in enumerate(expected):
            assert "%d" % record["step"][i] == row["step"]
            for key in ("time", "length", "x1", "y1", "x2", "y2"):
                assert "%.17g" % record[key][i] == row[key], key
            for key in ("fracture", "number"):
                assert "%d" % record[key][i] == row[key], key
            assert (record["type"][i], record["mode"][i]) == (row["type"], row["mode"])
    assert (taken, sim.time) == (4, 4.0)
    with pytest.raises(Exception, match="broken_bonds is not for a mechanics simulation"):
        hydrodda.Simulation(hydrodda.Scenario.load(VERIFICATION / "free_fall.toml"), threads=1).broken_bonds


def test_a_coupled_transient_step_that_throws_the_block_ends_with_no_equilibrium_as_the_program_says(in_tmp):
    """The jacked block whose mouths' head jumps to 1.1 H* in its fifth step
    (tests/cli/scenarios/jacking_in_time.toml; H* = rho_r h / rho_w = 2.5 m, Terzaghi's heave):
    the program ends with status "no equilibrium" (exit 1), the last state that held time step 4
    at t = 4e5 s. hydrodda.run returns that status, message and last_held, and a Simulation
    stepped to the end says them in its summary, never "not converged": the same steps on the
    same blocks, an exact identity with summary.json (no tolerance)."""
    scenario = hydrodda.Scenario.load(SOURCE_DIR / "tests/cli/scenarios/jacking_in_time.toml")
    code, _, err = run_program("run", scenario.file, "-o", "prog", "--threads", "1", cwd=in_tmp)
    assert code == 1, err
    program = json.loads((in_tmp / "prog" / "summary.json").read_text())
    assert (program["status"], program["iterations"]) == ("no equilibrium", 4)
    assert program["last_held"]["state"] == "time step 4, t = 400000 s"
    assert program["message"].startswith("time step 5 from t = 400000 s to 400050 s")

    result = hydrodda.run(scenario, "run", threads=1)
    assert (result.status, result.converged, result.iterations) == ("no equilibrium", False, 4)
    assert result.message == program["message"]
    for key in ("status", "converged", "message", "time", "iterations", "last_held"):
        assert result.summary[key] == program[key], key

    sim = hydrodda.Simulation(scenario, threads=1)
    assert sim.step(10) == 4  # the fifth step fails at the floor: no more are taken
    assert (sim.finished, sim.time) == (True, 4.0e5)
    assert sim.step() == 0
    summary = sim.summary
    for key in ("status", "converged", "message", "time", "iterations", "last_held"):
        assert summary.get(key) == program[key], key


def test_a_head_rising_through_the_jacking_head_ends_with_no_equilibrium_as_the_program_says(in_tmp):
    """The jacked block whose mouths' head rises slowly through H* = 2.5 m
    (tests/cli/scenarios/jacking_ramp_in_time.toml): the last step, at the floor, throws the block
    in its second iteration, steady passes from the last step that held throw it too, and the
    program ends with status "no equilibrium" (exit 1). hydrodda.run returns what summary.json
    says, and a Simulation stepped to the end says it in its summary: the same steps on the same
    blocks, an exact identity (no tolerance)."""
    scenario = hydrodda.Scenario.load(SOURCE_DIR / "tests/cli/scenarios/jacking_ramp_in_time.toml")
    code, _, err = run_program("run", scenario.file, "-o", "prog", "--threads", "1", cwd=in_tmp)
    assert code == 1, err
    program = json.loads((in_tmp / "prog" / "summary.json").read_text())
    steps = program["iterations"]
    assert program["status"] == "no equilibrium"
    assert program["last_held"]["step"] == steps
    assert "in its iteration 2, after the first held them" in program["message"]

    result = hydrodda.run(scenario, "run", threads=1)
    assert (result.status, result.converged, result.iterations) == ("no equilibrium", False, steps)
    for key in ("status", "converged", "message", "time", "iterations", "last_held"):
        assert result.summary[key] == program[key], key

    sim = hydrodda.Simulation(scenario, threads=1)
    assert sim.step(100) == steps  # the next step fails at the floor: no more are taken
    assert (sim.finished, sim.time) == (True, program["time"])
    summary = sim.summary
    for key in ("status", "converged", "message", "time", "iterations", "last_held"):
        assert summary.get(key) == program[key], key


def test_a_static_model_cut_short_of_rest_says_it_did_not_converge_as_its_run_does(in_tmp):
    """A static mechanics model whose steps end with its blocks still moving (the pushed block at
    a time step of 1e-4 s, two steps) is not converged, and says why as summary.json does."""
    scenario = hydrodda.Scenario.load(SOURCE_DIR / "tests/cli/scenarios/pushed_block.toml")
    scenario.set("mechanics.time_step", 1.0e-4)
    scenario.set("mechanics.steps", 2)
    sim = hydrodda.Simulation(scenario, threads=1)
    while not sim.finished:
        sim.step()
    result = hydrodda.run(scenario, "run")
    assert (result.converged, result.summary["converged"], sim.summary["converged"]) == (False, False, False)
    assert sim.summary["message"] == result.summary["message"]
    assert "raise mechanics.steps" in sim.summary["message"]


def test_blocks_name_their_material_as_the_summary_does(in_tmp):
    """Each block's material is the one whose region holds its centroid (mudstone, without a
    region, the rest): sandstone below y = 10 m, siltstone above 20 m. A run's blocks name the
    same as its summary.json."""
    scenario = hydrodda.Scenario.load(VERIFICATION / "three_layer_column.toml")
    blocks = hydrodda.Simulation(scenario).blocks
    y = blocks["centroid"][:, 1]
    assert blocks["material"].shape == y.shape == (15,)
    expected = np.where(y < 10.0, "sandstone", np.where(y > 20.0, "siltstone", "mudstone"))
    np.testing.assert_array_equal(blocks["material"], expected)
    result = hydrodda.run(scenario, "run")
    assert result.blocks["material"].tolist() == [b["material"] for b in result.summary["blocks"]]
    assert result.blocks["material"].tolist() == expected.tolist()
