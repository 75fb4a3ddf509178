"""pound.Model: reading, the expanded model, the checks, modes, and bad input."""

import json

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
