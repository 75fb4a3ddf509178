"""pound.batch (files, dicts, resume, the same numbers as `pound batch`) and pound.verify."""

import csv
import json
import subprocess

import numpy as np
import pytest

import pound


def girders_set(repository):
    """Two girders under the four bundled records at two scales: 8 cases."""
    return {
        "title": "two girders, bundled records",
        "models": [str(repository / "models" / "two_sdof_girders.json")],
        "records": [{"folder": str(repository / "ground_motions"), "pattern": "synthetic_*.AT2",
                     "units": "g"}],
        "scales": [0.5, 1.0],
        "histories": False,
    }


def rows(path):
    with open(path, newline="") as file:
        return [{k: v for k, v in row.items() if k != "run_time_s"} for row in csv.DictReader(file)]


def test_a_batch_from_a_dict_gives_the_rows_of_pound_batch_and_resumes(repository, pound_program,
                                                                       tmp_path):
    set_dict = girders_set(repository)
    set_file = tmp_path / "set.json"
    set_file.write_text(json.dumps(set_dict))
    subprocess.run([pound_program, "batch", str(set_file), "--out", str(tmp_path / "cli"), "-q",
                    "--jobs", "1"], check=True)
    report = pound.batch(set_dict, tmp_path / "python", jobs=2)
    print(report)
    assert report["cases"] == 8 and report["completed"] == 8 and report["failed"] == 0
    assert rows(tmp_path / "cli" / "batch_summary.csv") == rows(report["summary"])
    again = pound.batch(set_dict, tmp_path / "python", resume=True)
    assert again["resumed"] == 8 and again["ran"] == 0
    with pytest.raises(pound.InputError) as raised:
        pound.batch(set_dict, tmp_path / "python")  # without resume: a batch is there
    print(raised.value)
    from_file = pound.batch(set_file, tmp_path / "file", jobs=1)
    assert rows(from_file["summary"]) == rows(report["summary"])


def test_a_bad_set_is_an_input_error_with_its_path(repository, tmp_path):
    set_dict = girders_set(repository)
    set_dict["scales"] = [1.0, "twice"]
    with pytest.raises(pound.InputError) as raised:
        pound.batch(set_dict, tmp_path / "out")
    print(raised.value)
    assert raised.value.file == "<dict>" and raised.value.path == "/scales/1"
    assert not (tmp_path / "out").exists()


def test_rod_impact_gives_the_metrics_of_pound_verify(pound_program):
    printed = json.loads(subprocess.run(
        [pound_program, "verify", "rod-impact", "--n", "50", "--law", "hard_contact", "--json"],
        capture_output=True, text=True, check=True).stdout)
    metrics = pound.verify.rod_impact(n=50, law="hard_contact")
    for key in ("force_l2_error", "duration_error", "separation_velocity_error",
                "peak_force_ratio", "steps"):
        assert metrics[key] == printed[key], key
    print(f"force_l2_error {metrics['force_l2_error']:.4f}")
    assert len(metrics["time"]) == len(metrics["force"]) == len(metrics["exact_force"])
    assert np.max(metrics["exact_force"]) > 0


def test_rod_impact_names_bad_arguments_as_python_does():
    with pytest.raises(pound.InputError, match="^n must be >= 1"):
        pound.verify.rod_impact(n=0)
    with pytest.raises(pound.InputError, match="k_ratio must be > 0"):
        pound.verify.rod_impact(k_ratio=-1.0)
    with pytest.raises(pound.InputError, match="unknown rod-impact case"):
        pound.verify.rod_impact(case="nope")
    with pytest.raises(pound.InputError, match="^dt_ratio: the time step .* longer than the whole run"):
        pound.verify.rod_impact(dt_ratio=1e308)
    with pytest.raises(pound.InputError, match="^alpha is not a parameter of newmark_average_acceleration"):
        pound.verify.rod_impact(alpha=-0.05)
    with pytest.raises(pound.InputError, match="^eta is the extended penalty's damping factor"):
        pound.verify.rod_impact(eta=2.0)
    with pytest.raises(TypeError, match="elements"):
        pound.verify.rod_impact(elements=10)
    with pytest.raises(pound.InputError) as raised:
        pound.verify.rod_impact(n="ten")
    assert raised.value.path == "n" and "integer" in raised.value.message


def test_restitution_is_achieved_by_every_calibrated_law():
    rows_ = pound.verify.restitution()["rows"]
    calibrated = [r for r in rows_ if r["calibrated"]]
    worst = max(abs(r["achieved"] - r["target"]) for r in calibrated)
    print(f"{len(calibrated)} calibrated laws and targets, worst |achieved - target| {worst:.2e}")
    assert calibrated and worst <= 0.005


def test_two_element_eigenvalues_match_the_closed_forms():
    results = pound.verify.two_element()["cases"]
    worst = max(r["relative_error"] for r in results)
    print(f"worst relative error {worst:.2e}")
    assert worst <= 1e-10


def test_batch_progress_goes_from_the_first_case_to_the_last(repository, tmp_path):
    calls = []
    report = pound.batch(girders_set(repository), tmp_path / "out", jobs=2,
                         progress=lambda done, total: calls.append((done, total)))
    print(len(calls), calls[:3], calls[-3:])
    assert report["completed"] == 8
    assert calls[-1] == (8, 8) and all(total == 8 for _, total in calls)
    done = [d for d, _ in calls]
    assert all(0 <= d <= 8 for d in done) and done == sorted(done)
    calls.clear()
    again = pound.batch(girders_set(repository), tmp_path / "out", resume=True,
                        progress=lambda done, total: calls.append((done, total)))
    assert again["ran"] == 0 and calls == []  # nothing ran: no call


def test_what_batch_progress_raises_stops_the_batch_and_reaches_the_caller(repository, tmp_path):
    def stop(done, total):
        raise RuntimeError(f"stopped at {done} of {total}")

    with pytest.raises(RuntimeError, match="^stopped at .* of 8.0$"):
        pound.batch(girders_set(repository), tmp_path / "out", jobs=2, progress=stop)
    assert not (tmp_path / "out" / "batch_summary.csv").exists()
    rest = pound.batch(girders_set(repository), tmp_path / "out", resume=True)
    print(rest)
    assert rest["completed"] == 8 and rest["resumed"] + rest["ran"] == 8
    whole = pound.batch(girders_set(repository), tmp_path / "whole")
    assert rows(rest["summary"]) == rows(whole["summary"])


def test_batch_progress_must_be_callable(repository, tmp_path):
    with pytest.raises(pound.InputError, match="progress"):
        pound.batch(girders_set(repository), tmp_path / "out", progress=1)


def test_a_batch_names_out_and_resume_as_python_arguments(repository, tmp_path):
    pound.batch(girders_set(repository), tmp_path / "out")
    with pytest.raises(pound.InputError) as raised:
        pound.batch(girders_set(repository), tmp_path / "out")
    print(raised.value)
    assert "add resume=True to finish it, or choose another out" in str(raised.value)
    assert "--" not in str(raised.value)


def test_ctrl_c_stops_a_batch_with_keyboard_interrupt(repository, tmp_path, signalled):
    model = json.loads((repository / "models" / "two_sdof_girders.json").read_text())
    model["analysis"]["duration"] = 2.0e4  # about 2 s a case past its record, 8 cases
    (tmp_path / "long.json").write_text(json.dumps(model))
    set_dict = girders_set(repository)
    set_dict["models"] = [str(tmp_path / "long.json")]
    done = signalled(f"""
try:
    pound.batch(json.loads({json.dumps(set_dict)!r}), {str(tmp_path / "out")!r}, jobs=2)
except KeyboardInterrupt:
    print("interrupted after", round(time.monotonic() - start, 2))
""")
    assert "interrupted after" in done.stdout
    assert float(done.stdout.split("interrupted after")[1].split()[0]) < 2.0


def test_a_set_dict_may_name_its_files_with_pathlib(repository, tmp_path):
    set_dict = girders_set(repository)
    set_dict["models"] = [repository / "models" / "two_sdof_girders.json"]
    set_dict["records"][0]["folder"] = repository / "ground_motions"
    report = pound.batch(set_dict, tmp_path / "out")
    assert report["completed"] == 8
