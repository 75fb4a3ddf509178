"""pound.Model: reading, the expanded model, the checks, modes, pushovers, and bad input."""

import csv
import json
import subprocess

import numpy as np
import pytest

import pound


def two_girders(models):
    """The bundled two-girder model as a dict, its record path made absolute."""
    model = json.loads((models / "two_sdof_girders.json").read_text())
    record = model["excitations"][0]["record"]
    model["excitations"][0]["record"] = str((models / record).resolve())
    return model


def test_a_model_file_and_the_same_dict_give_the_same_model(models):
    from_file = pound.Model.from_file(models / "two_sdof_girders.json")
    text = (models / "two_sdof_girders.json").read_text()
    from_dict = pound.Model.from_dict(json.loads(text), folder=models)
    assert from_file.expand() == from_dict.expand()
    assert pound.Model.from_dict(two_girders(models)).path == "<dict>"
    assert from_file.to_dict()["title"].startswith("The textbook case")


def test_expand_replaces_the_generators(models):
    expanded = pound.Model.from_file(models / "three_span_bridge.json").expand()
    assert "girder_bridge" not in expanded
    assert len(expanded["nodes"]) > 20 and len(expanded["links"]) > 5


def test_check_gives_the_periods_of_the_two_oscillators(models):
    check = pound.Model.from_file(models / "two_sdof_girders.json").check()
    assert check["dofs"] == 2
    # T = 0.6 s and 1.2 s by construction (k = 4 pi^2 m / T^2).
    periods = sorted(check["periods"])
    print(f"periods {periods}, errors {periods[0] - 0.6:.2e} {periods[1] - 1.2:.2e}")
    assert periods == pytest.approx([0.6, 1.2], rel=1e-3)
    assert check["links"][0]["id"] == "joint"


def test_modes_give_periods_and_unit_shapes(models):
    modes = pound.Model.from_file(models / "two_sdof_girders.json").modes(2)
    assert [m["mode"] for m in modes["modes"]] == [1, 2]
    assert modes["modes"][0]["period"] == pytest.approx(1.2, rel=1e-3)
    assert modes["shapes"].shape == (2, 2)
    assert np.max(np.abs(modes["shapes"]), axis=0) == pytest.approx([1.0, 1.0])
    assert sorted(modes["dofs"]) == ["girder_1.u_x", "girder_2.u_x"]


def test_numpy_numbers_are_taken_as_numbers(models):
    model = two_girders(models)
    model["links"][0]["gap"] = np.float64(0.05)
    model["masses"][0]["mass"] = np.int64(400000)
    model["nodes"][0]["x"] = np.array(-1.0)
    assert pound.Model.from_dict(model).expand()["links"][0]["gap"] == 0.05


@pytest.mark.parametrize("change, path, words", [
    (lambda m: m["links"][0].update(gap="wide"), "/links/0/gap", "number"),
    (lambda m: m["links"][0].update(gap=float("nan")), "/links/0/gap", "finite"),
    (lambda m: m["links"][0].update(gap=np.array([np.inf])), "/links/0/gap/0", "finite"),
    (lambda m: m["links"][0].update(nodes=["girder_1", "girder_9"]), "/links/0/nodes/1",
     "girder_9"),
    (lambda m: m["links"][0].pop("nodes"), "/links/0/nodes", "missing"),
    (lambda m: m["links"][0].update(gpa=0.05), "/links/0/gpa", "gap"),
    (lambda m: m["links"][0].update(gap=object()), "/links/0/gap", "object"),
    (lambda m: m["excitations"][0].update(record="no_such_record.AT2"), "/excitations/0/record",
     "no_such_record"),
])
def test_bad_dicts_raise_input_error_with_the_json_path(models, change, path, words):
    model = two_girders(models)
    change(model)
    with pytest.raises(pound.InputError) as raised:
        pound.Model.from_dict(model, name="girders")
    error = raised.value
    print(f"{error}")
    assert error.file == "girders"
    assert error.path == path
    assert words in error.message


def test_a_missing_file_and_a_non_dict_are_input_errors(tmp_path):
    with pytest.raises(pound.InputError) as raised:
        pound.Model.from_file(tmp_path / "missing.json")
    assert "missing.json" in raised.value.file
    with pytest.raises(pound.InputError):
        pound.Model.from_dict([1, 2])
    (tmp_path / "broken.json").write_text('{"nodes": [}')
    with pytest.raises(pound.InputError) as raised:
        pound.Model.from_file(tmp_path / "broken.json")
    assert "line 1" in str(raised.value)


def test_records_of_a_dict_are_found_from_its_folder(models):
    model = json.loads((models / "two_sdof_girders.json").read_text())
    with pytest.raises(pound.InputError):
        pound.Model.from_dict(model, folder="/")
    assert pound.Model.from_dict(model, folder=models).check()["dofs"] == 2


def cantilever(length=8.0, inertia=0.8, youngs_modulus=3.0e10):
    """A column of two beams fixed at its base, a mass at its top: K = 3 E I / L^3 at the top."""
    return {
        "title": "cantilever",
        "dimension": 2,
        "nodes": [{"id": "base", "x": 0.0, "y": 0.0}, {"id": "mid", "x": 0.0, "y": length / 2},
                  {"id": "top", "x": 0.0, "y": length}],
        "materials": [{"id": "concrete", "youngs_modulus": youngs_modulus, "density": 0.0}],
        "elements": [{"id": "lower", "type": "beam", "nodes": ["base", "mid"],
                      "material": "concrete", "area": 3.0, "inertia": inertia},
                     {"id": "upper", "type": "beam", "nodes": ["mid", "top"],
                      "material": "concrete", "area": 3.0, "inertia": inertia}],
        "masses": [{"node": "top", "mass": 1.0e5}],
        "supports": [{"node": "base", "fix": ["x", "y", "rz"]}],
        "analysis": {"time_step": 0.01, "duration": 1.0},
    }


def test_a_pushover_of_a_cantilever_has_its_closed_form_stiffness(tmp_path):
    model = pound.Model.from_dict(cantilever())
    push = model.pushover("top", 0.01, increments=4, out=tmp_path)
    exact = 3 * 3.0e10 * 0.8 / 8.0**3
    error = abs(push.summary["initial_stiffness"] / exact - 1)
    print(push)
    print(f"initial stiffness {push.summary['initial_stiffness']:.6g} against 3EI/L^3 "
          f"{exact:.6g}: relative error {error:.1e}")
    assert error < 1e-9  # cubic beams are exact under a tip load: round-off only
    assert push.completed and push.summary["reached"] == pytest.approx(0.01)
    assert list(push.curve["displacement"]) == pytest.approx([0, 0.0025, 0.005, 0.0075, 0.01])
    assert push.curve["base_shear"] == pytest.approx(exact * push.curve["displacement"])
    assert (tmp_path / "pushover.csv").exists() and (tmp_path / "pushover.json").exists()
    assert push.to_pandas().shape == (5, 3)


def test_a_pushover_gives_what_pound_pushover_writes(models, pound_program, tmp_path):
    model_path = models / "three_span_bridge_takeda.json"
    push = pound.Model.from_file(model_path).pushover("bridge.p1.top", 0.04)
    subprocess.run([pound_program, "pushover", str(model_path), "--node", "bridge.p1.top",
                    "--to", "0.04", "--out", str(tmp_path)], check=True, capture_output=True)
    written = json.loads((tmp_path / "pushover.json").read_text())
    assert written == push.summary
    assert push.summary["first_yield"]["link"] == "bridge.p1.hinge"
    with open(tmp_path / "pushover.csv", newline="") as file:
        rows = list(csv.DictReader(file))
    # The file's header gives each column's unit: "displacement [m]", "base_shear" (no mass unit).
    named = {header.split(" [")[0]: header for header in rows[0]}
    assert list(named) == list(push.curve)
    assert named["displacement"] == "displacement [m]"
    for column, values in push.curve.items():
        assert [float(row[named[column]]) for row in rows] == list(values), column


def test_a_pushover_that_cannot_reach_its_target_is_an_analysis_error():
    # A block that only a slack restrainer ties to the girder: the girder's mass pattern loads
    # it, and pushed toward the girder nothing holds it.
    model = pound.Model.from_dict({
        "dimension": 1,
        "nodes": [{"id": "ground", "x": 0}, {"id": "girder", "x": 1}, {"id": "block", "x": 2}],
        "materials": [{"id": "pier", "youngs_modulus": 1e7, "density": 0}],
        "elements": [{"id": "pier", "type": "truss", "nodes": ["ground", "girder"],
                      "material": "pier", "area": 1}],
        "masses": [{"node": "girder", "mass": 1000}, {"node": "block", "mass": 100}],
        "supports": [{"node": "ground", "fix": ["x"]}],
        "links": [{"id": "tie", "nodes": ["girder", "block"], "axis": [1],
                   "law": {"type": "restrainer", "stiffness": 1e8, "slack": 0.05}}],
        "analysis": {"time_step": 0.01, "duration": 1}})
    with pytest.raises(pound.AnalysisError) as raised:
        model.pushover("girder", -0.04, pattern="mass")
    print(raised.value)
    assert raised.value.time is None and not raised.value.result.completed
    assert "The pattern loads node 'block', direction x" in raised.value.reason
    push = model.pushover("girder", -0.04, pattern="mass", check=False)
    assert push.stopped == raised.value.reason


def test_the_bundled_bridge_takes_a_mass_pattern(models):
    push = pound.Model.from_file(models / "three_span_bridge.json").pushover(
        "bridge.p1.top", 0.04, pattern="mass")
    assert push.completed


def test_pushover_arguments_are_input_errors_naming_them(models):
    model = pound.Model.from_file(models / "three_span_bridge_takeda.json")
    bad = {"node": [dict(node="nope", to=0.04), dict(node=3, to=0.04),
                    dict(node="bridge.p1.base", to=0.04)],  # fixed
           "to": [dict(node="bridge.p1.top", to=0), dict(node="bridge.p1.top", to=float("nan")),
                  dict(node="bridge.p1.top", to="0.04"), dict(node="bridge.p1.top", to=1e-12)],
           "direction": [dict(node="bridge.p1.top", to=0.04, direction="z")],
           "pattern": [dict(node="bridge.p1.top", to=0.04, pattern="uniform")],
           "increments": [dict(node="bridge.p1.top", to=0.04, increments=0),
                          dict(node="bridge.p1.top", to=0.04, increments=2.0)]}
    for where, arguments in bad.items():
        for given in arguments:
            with pytest.raises(pound.InputError) as raised:
                model.pushover(**given)
            print(given, "->", raised.value)
            assert raised.value.path == where
    with pytest.raises(pound.InputError, match="tied to its master along x") as raised:
        pound.Model.from_file(models / "diaphragm_storey_3d.json").pushover("top1", 0.01)
    assert raised.value.path == "node"


def test_a_1d_model_is_pushed_along_x_only(models):
    # y of a node of a 1-D model would be the next node's x (it read past the last node).
    model = pound.Model.from_file(models / "two_sdof_girders.json")
    for node in ("girder_1", "ground_2"):
        with pytest.raises(pound.InputError, match="1-D: its nodes move along x only") as raised:
            model.pushover(node, 0.05, direction="y")
        assert raised.value.path == "direction"


def test_ctrl_c_stops_a_pushover(models, signalled):
    done = signalled(f"""
model = pound.Model.from_file({str(models / "three_span_bridge_takeda.json")!r})
try:
    model.pushover("bridge.p1.top", 0.04, increments=1000000)
except KeyboardInterrupt:
    print("interrupted after", round(time.monotonic() - start, 2))
""")
    assert "interrupted after" in done.stdout
    assert float(done.stdout.split("interrupted after")[1].split()[0]) < 2.0
