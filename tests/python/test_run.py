"""pound.run: the same results as `pound run`, records given from Python, failures, threads."""

import json
import math
import pathlib
import signal
import subprocess
import threading

import numpy as np
import pytest

import pound

MODELS = sorted((pathlib.Path(__file__).resolve().parents[2] / "models").glob("*.json"))


def without_run_time(folder):
    summary = json.loads((folder / "summary.json").read_text())
    summary.pop("run_time_s")
    summary.get("verification", {}).pop("run_time_s", None)
    return summary


def assert_same_outputs(cli, python):
    """Every file of the two output folders byte for byte, summary.json but for its run time."""
    files = sorted(p.name for p in cli.iterdir())
    assert files == sorted(p.name for p in python.iterdir())
    for name in files:
        if name != "summary.json":
            assert (cli / name).read_bytes() == (python / name).read_bytes(), name
    assert without_run_time(cli) == without_run_time(python)


@pytest.mark.parametrize("model", MODELS, ids=[m.stem for m in MODELS])
def test_every_example_gives_the_results_of_pound_run_bit_for_bit(model, pound_program, tmp_path):
    subprocess.run([pound_program, "run", str(model), "--out", str(tmp_path / "cli"), "-q"],
                   check=True)
    result = pound.run(pound.Model.from_file(model), out=tmp_path / "python")
    assert_same_outputs(tmp_path / "cli", tmp_path / "python")
    # The arrays are the values written: each CSV column read back equals its array.
    for file, columns in result.tables.items():
        if not file.endswith(".csv"):
            continue
        header = (tmp_path / "cli" / file).read_text().splitlines()[0].split(",")
        data = np.atleast_2d(np.loadtxt(tmp_path / "cli" / file, delimiter=",", skiprows=1,
                                        dtype=str))
        for k, name in enumerate(header):
            name = name.split(" [")[0]
            if isinstance(columns.get(name), np.ndarray):
                assert np.array_equal(columns[name], data[:, k].astype(float)), (file, name)


def test_a_record_from_a_file_or_from_arrays_runs_as_pound_run_motion(models, repository,
                                                                      pound_program, tmp_path):
    record_path = repository / "ground_motions" / "synthetic_soft_01.AT2"
    model = models / "two_sdof_girders.json"
    subprocess.run([pound_program, "run", str(model), "--motion", str(record_path), "--out",
                    str(tmp_path / "cli"), "-q"], check=True)
    from_file = pound.Record.from_file(record_path)
    pound.run(pound.Model.from_file(model), from_file, out=tmp_path / "file")
    from_arrays = pound.Record(from_file.time_step, from_file.accelerations, "g")
    arrays = pound.run(model, from_arrays, out=tmp_path / "arrays")
    assert (tmp_path / "cli" / "joint.csv").read_bytes() == (tmp_path / "file" /
                                                             "joint.csv").read_bytes()
    assert (tmp_path / "cli" / "joint.csv").read_bytes() == (tmp_path / "arrays" /
                                                             "joint.csv").read_bytes()
    applied = arrays.summary["excitations"][0]
    assert applied["replaced_by"] == "pound.run(record=...)"
    assert applied["format"] == "samples"


def test_a_record_in_m_s2_with_times_equals_the_same_in_g(models):
    g = 9.80665
    times = np.arange(2001) * 0.01
    accelerations = 0.3 * np.sin(2 * np.pi * times) * np.exp(-0.2 * times)
    in_g = pound.run(models / "two_sdof_girders.json", pound.Record(0.01, accelerations, "g"))
    in_si = pound.run(models / "two_sdof_girders.json",
                      pound.Record(times, accelerations * g, "m/s2"))
    difference = np.max(np.abs(in_g.links["joint"]["force"] - in_si.links["joint"]["force"]))
    peak = np.max(in_g.links["joint"]["force"])
    print(f"peak force {peak:.6g}, largest difference {difference:.3g}")
    assert difference <= 1e-9 * peak


def test_a_scaled_record_scales_a_linear_response(models):
    model = json.loads((models / "two_sdof_girders.json").read_text())
    model.pop("links")
    model.pop("monitors")
    model["recorders"] = [{"type": "node", "nodes": ["girder_1"], "file": "girder.csv"}]
    model = pound.Model.from_dict(model, folder=models)
    times = np.arange(1001) * 0.01
    shake = 0.2 * np.sin(3 * times)
    once = pound.run(model, pound.Record(0.01, shake, scale=1.0)).nodes["girder_1"]["u_x"]
    thrice = pound.run(model, pound.Record(0.01, shake, scale=3.0)).nodes["girder_1"]["u_x"]
    error = np.max(np.abs(thrice - 3 * once)) / np.max(np.abs(3 * once))
    print(f"linear scaling error {error:.2e}")
    assert error < 1e-12


def test_a_failed_run_raises_analysis_error_with_the_result_so_far(models):
    with pytest.raises(pound.AnalysisError) as raised:
        pound.run(models / "two_sdof_girders.json", max_steps=100)
    error = raised.value
    print(error)
    assert "100 steps" in error.reason
    assert error.result is not None and not error.result.completed
    assert len(error.result.links["joint"]["force"]) == 101
    assert error.time == pytest.approx(100 * 0.002)
    result = pound.run(models / "two_sdof_girders.json", max_steps=100, check=False)
    assert result.summary["status"] == "failed"


def test_outputs_never_overwrite_an_input(tmp_path, models):
    record = tmp_path / "motion.csv"
    record.write_text("\n".join(f"{0.1 * np.sin(k / 10):.6f}" for k in range(500)) + "\n")
    model = json.loads((models / "two_sdof_girders.json").read_text())
    model["recorders"] = [{"type": "link", "file": "motion.csv"}]
    model["excitations"] = [{"record": str(record), "time_step": 0.01}]
    before = record.read_bytes()
    with pytest.raises(pound.InputError) as raised:
        pound.run(pound.Model.from_dict(model), out=tmp_path)
    print(raised.value)
    assert "motion.csv" in str(raised.value)
    model["excitations"] = []
    model["analysis"]["duration"] = 4.0
    with pytest.raises(pound.InputError) as raised:
        pound.run(pound.Model.from_dict(model), pound.Record.from_file(record, dt=0.01),
                  out=tmp_path)
    print(raised.value)
    assert record.read_bytes() == before and not (tmp_path / "summary.json").exists()
    # Named as this function's argument, not as the program's option --out.
    named_summary = tmp_path / "summary.json"
    named_summary.write_bytes(before)
    with pytest.raises(pound.InputError) as raised:
        pound.run(models / "two_sdof_girders.json", pound.Record.from_file(named_summary, dt=0.01),
                  out=tmp_path)
    print(raised.value)
    assert raised.value.path == "out" and named_summary.read_bytes() == before


def test_wrong_arguments_are_input_errors_naming_them(models):
    with pytest.raises(pound.InputError) as raised:
        pound.run(42)
    assert raised.value.path == "model"
    with pytest.raises(pound.InputError) as raised:
        pound.run(models / "two_sdof_girders.json", "synthetic_firm_01.AT2")
    print(raised.value)
    assert raised.value.path == "record" and "pound.Record" in raised.value.message


def test_a_count_given_as_a_fraction_is_refused_not_cut(models, repository, tmp_path):
    # max_steps=3.5 ran 3 steps; the program refuses --max-steps 3.5.
    model = pound.Model.from_file(models / "two_sdof_girders.json")
    record = repository / "ground_motions" / "synthetic_firm_01.AT2"
    calls = {"max_steps": lambda v: pound.run(model, max_steps=v, histories=False),
             "count": lambda v: model.modes(count=v),
             "column": lambda v: pound.Record.from_file(record, column=v),
             "jobs": lambda v: pound.batch({"models": [], "records": []}, tmp_path / "b", jobs=v)}
    for where, call in calls.items():
        for value in (3.5, True, float("nan"), "2"):
            with pytest.raises(pound.InputError) as raised:
                call(value)
            print(raised.value)
            assert raised.value.path == where and "expected an integer" in raised.value.message
    assert pound.run(model, max_steps=np.int64(3), histories=False, check=False).summary["steps"] == 3


def test_results_hold_tables_units_and_a_data_frame(models):
    result = pound.run(models / "adjacent_buildings_outputs.json")
    assert result.completed and result.warnings == result.summary.get("warnings", [])
    assert set(result.tables) == {f for f in result.tables}
    assert result.time[0] == 0.0 and np.all(np.diff(result.time) > 0)
    for item in result.links.values():
        assert len(item["force"]) == len(item["time"])
    frame = result.to_pandas()
    assert frame.index.name == "time" and len(frame) == len(result.time)
    link = next(iter(result.links))
    assert result.link_summaries[link]["peak_force"] == pytest.approx(
        max(0.0, np.max(result.links[link]["force"])))
    assert np.array_equal(frame[f"{link}.force"].to_numpy(), result.links[link]["force"])
    arrays = result.links[link]["force"]
    with pytest.raises(ValueError):
        arrays[0] = 1.0  # views of the results: read-only


def test_an_item_two_recorders_hold_is_taken_from_the_one_with_every_step(models):
    # A roof recorded every 0.05 s for a plot and at every step: nodes[] and to_pandas() took the
    # thinned copy (the first recorder), and the roof's peak acceleration read 24 % low.
    model = json.loads((models / "adjacent_buildings.json").read_text())
    model["recorders"] = [
        {"type": "node", "nodes": ["pair.left.f5"], "interval": 0.05, "file": "roof_plot.csv"},
        {"type": "node", "nodes": ["pair.left.f5"], "file": "roof_full.csv"}]
    result = pound.run(pound.Model.from_dict(model, folder=models))
    full = result.tables["roof_full.csv"]["pair.left.f5.a_abs_x"]
    assert len(result.tables["roof_plot.csv"]["time"]) < len(full)
    assert np.array_equal(result.nodes["pair.left.f5"]["a_abs_x"], full)
    frame = result.to_pandas()
    assert np.array_equal(frame["pair.left.f5.a_abs_x"].to_numpy(), full)


def oscillator_in_milliseconds():
    """A 1000 kg oscillator of T = 1 s, 5 % mass-proportional damping, in kg, m and ms."""
    return pound.Model.from_dict({
        "dimension": 1, "units": {"length": "m", "time": "ms", "mass": "kg"},
        "nodes": [{"id": "ground", "x": 0}, {"id": "top", "x": 1}],
        "materials": [{"id": "col", "youngs_modulus": 4e-3 * math.pi ** 2, "density": 0}],
        "elements": [{"id": "col", "type": "truss", "nodes": ["ground", "top"],
                      "material": "col", "area": 1}],
        "masses": [{"node": "top", "mass": 1000, "mass_damping": 2e-4 * math.pi}],
        "supports": [{"node": "ground", "fix": ["x"]}],
        "analysis": {"time_step": 5.0, "duration": 4000.0},
        "recorders": [{"type": "node", "nodes": ["top"], "file": "top.csv"}]}, name="ms.json")


def test_a_millisecond_models_records_take_their_own_unit_of_time(tmp_path):
    # The same samples, their step given in ms, in s, in the model's unit (ms, no time_unit), or
    # read from a file that states dt = 0.01 s with dt=0.01 beside it (Record.from_file takes a
    # file's times in seconds): one response. from_file's dt was checked in seconds and then
    # read by the run in ms, so no value of it ran (audit 71).
    samples = 0.2 * np.sin(np.arange(300) * 0.05)
    (tmp_path / "sine.txt").write_text("# dt=0.01 s, acceleration in g\n" +
                                       "\n".join(f"{a:.17g}" for a in samples) + "\n")
    model = oscillator_in_milliseconds()
    runs = {name: pound.run(model, record) for name, record in {
        "ms": pound.Record(10.0, samples, time_unit="ms"),
        "s": pound.Record(0.01, samples, time_unit="s"),
        "model's": pound.Record(10.0, samples),
        "file": pound.Record.from_file(tmp_path / "sine.txt", dt=0.01)}.items()}
    reference = runs["ms"].nodes["top"]["u_x"]
    print({name: float(np.max(np.abs(run.nodes["top"]["u_x"]))) for name, run in runs.items()})
    assert np.max(np.abs(reference)) > 0.0
    for name, run in runs.items():
        assert np.allclose(run.nodes["top"]["u_x"], reference, rtol=0, atol=1e-12 *
                           np.max(np.abs(reference))), name


def test_element_histories_and_envelopes(models):
    model = json.loads((models / "three_span_bridge.json").read_text())
    envelope = next(r for r in model["recorders"] if r["type"] == "element")
    model["recorders"].append(dict(envelope, envelope=False, file="pier_forces.csv"))
    result = pound.run(pound.Model.from_dict(model, folder=models))
    assert set(result.elements) == set(envelope["elements"])
    forces = result.elements[envelope["elements"][0]]
    assert len(forces) > 2 and all(len(v) == len(forces["time"]) for v in forces.values())
    # The envelope table holds each quantity's peak of the same history.
    table = result.tables[envelope["file"]]
    print({k: v[:3] for k, v in table.items()})
    quantity = next(q for q in forces if q != "time")
    row = list(table["quantity"]).index(f"{envelope['elements'][0]}.{quantity}")
    assert table["max"][row] == np.max(forces[quantity])


def test_without_histories_only_the_summary_is_kept(models):
    result = pound.run(models / "two_sdof_girders.json", histories=False)
    assert result.tables == {} and result.links == {} and result.time is None
    assert result.to_pandas().empty
    assert result.link_summaries["joint"]["impacts"] > 0


def test_threads_run_in_parallel_with_the_results_of_one_thread(models):
    model = pound.Model.from_file(models / "three_span_bridge.json")
    alone = pound.run(model).links
    results = [None] * 4

    def run(k):
        results[k] = pound.run(model).links

    threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for links in results:
        for link, quantities in alone.items():
            assert np.array_equal(links[link]["force"], quantities["force"]), link


def test_the_gil_is_released_while_a_run_solves(models):
    # A Python loop on this thread goes on while another thread's run solves; with the GIL held
    # it would stand still for the whole solve.
    runner = threading.Thread(target=pound.run,
                              args=(models / "block_on_belt_hard_contact.json",),
                              kwargs={"histories": False})
    loops = 0
    runner.start()
    while runner.is_alive():
        loops += 1
    runner.join()
    print(f"{loops} loops of this thread during the run")
    assert loops > 100000


def test_ctrl_c_stops_a_run_with_keyboard_interrupt(models, signalled):
    long_model = models / "block_on_belt.json"  # about 3 s
    done = signalled(f"""
model = pound.Model.from_file({str(long_model)!r})
try:
    pound.run(model, max_steps=0)
except KeyboardInterrupt:
    print("interrupted after", round(time.monotonic() - start, 2))
    pound.run({str(models / "rod_impact.json")!r})  # the next run starts afresh
    print("next run completed")
""")
    assert "interrupted after" in done.stdout
    assert float(done.stdout.split("interrupted after")[1].split()[0]) < 2.0
    assert "next run completed" in done.stdout


def test_the_energy_terms_balance(models):
    # The terms of the energy balance (docs/design.md 2.4): what went in is held, damped or
    # taken by the links, to the balance error the run reports.
    energy = pound.run(models / "two_sdof_girders.json", histories=False).energy
    held = energy["kinetic"] + energy["strain"] + energy["damping"] + energy["links"]
    error = abs(held - energy["input"] - energy["initial"]) / energy["input"]
    print(f"balance error {error:.2e}, reported {energy['balance_error']:.2e}")
    assert energy["input"] > 0.0 and energy["links"] > 0.0
    assert error == pytest.approx(energy["balance_error"], abs=1e-12) and error < 1e-10


def block_on_belt(models, duration):
    """The block on a belt (central difference, 9e-8 s steps) for `duration` [s]: 0.0015 s is
    about 16,000 steps, some 0.8 s of solving."""
    model = json.loads((models / "block_on_belt.json").read_text())
    model["analysis"]["duration"] = duration
    return pound.Model.from_dict(model, name="block_on_belt", folder=models)


def test_progress_follows_the_solve_from_its_start_to_its_end(models):
    model = block_on_belt(models, 0.0015)
    calls = []
    result = pound.run(model, histories=False, progress=lambda t, end: calls.append((t, end)))
    print(len(calls), "calls:", calls[:3], "...", calls[-2:])
    assert calls[0] == (0.0, 0.0015)
    assert calls[-1] == (0.0015, 0.0015)
    times = [t for t, _ in calls]
    assert times == sorted(times) and len(set(times)) == len(times)
    assert all(end == 0.0015 for _, end in calls)
    assert len(calls) >= 3  # the start, at least one 0.2 s later, the end
    quiet = pound.run(model, histories=False)
    summary, quiet_summary = dict(result.summary), dict(quiet.summary)
    summary.pop("run_time_s")
    quiet_summary.pop("run_time_s")
    assert summary == quiet_summary


def test_what_progress_raises_stops_the_run_and_reaches_the_caller(models):
    class Enough(Exception):
        pass

    def stop_after_the_start(t, end):
        if t > 0.0:
            raise Enough(f"stopped at {t}")

    with pytest.raises(Enough, match="stopped at"):
        pound.run(block_on_belt(models, 0.004), histories=False, progress=stop_after_the_start)
    calls = []
    pound.run(models / "rod_impact.json", progress=lambda t, end: calls.append(t))
    assert calls[0] == 0.0 and calls[-1] > 0.0  # the next run starts afresh


def test_a_failed_runs_last_progress_call_is_at_its_failure(models):
    calls = []
    result = pound.run(models / "rod_impact.json", max_steps=10, check=False,
                       progress=lambda t, end: calls.append((t, end)))
    assert not result.completed
    assert calls[0][0] == 0.0 and calls[-1][0] == result.failure_time > 0.0
    assert all(t < end for t, end in calls)


def test_max_steps_zero_lifts_the_models_limit_and_none_keeps_it(models):
    model = json.loads((models / "two_sdof_girders.json").read_text())
    model["analysis"]["max_steps"] = 100
    limited = pound.Model.from_dict(model, folder=models)
    assert not pound.run(limited, histories=False, check=False).completed
    assert pound.run(limited, histories=False, max_steps=0).completed


def test_counts_and_seconds_out_of_range_are_input_errors_naming_them(models, tmp_path):
    for call, name in [(lambda: pound.run(models / "rod_impact.json", max_steps=-1), "max_steps"),
                       (lambda: pound.run(models / "rod_impact.json", time_limit=-1), "time_limit"),
                       (lambda: pound.run(models / "rod_impact.json", time_limit=float("nan")),
                        "time_limit"),
                       (lambda: pound.Model.from_file(models / "rod_impact.json").modes(count=0),
                        "count"),
                       (lambda: pound.batch(models / "../sets/three_span_bridge_ida.json",
                                            tmp_path / "b", jobs=-1), "jobs")]:
        with pytest.raises(pound.InputError, match=name):
            call()
    assert not (tmp_path / "b").exists()


def test_progress_must_be_callable(models):
    with pytest.raises(pound.InputError, match="progress"):
        pound.run(models / "rod_impact.json", progress=0.5)


def test_an_ensemble_gives_every_numbers_spread_and_writes_ensemble_json(models, tmp_path):
    # The bundled bridge: its numbers spread, none past the threshold since its backwalls are held
    # (README); the energies are judged against the largest energy term.
    calls = []
    result = pound.run(models / "three_span_bridge.json", out=tmp_path / "python", ensemble=4,
                       jobs=2, progress=lambda done, runs: calls.append((done, runs)))
    print(result.report)
    print(calls)
    assert calls[0] == (0.0, 5.0) and calls[-1] == (5.0, 5.0)
    assert [done for done, _ in calls] == sorted(done for done, _ in calls)
    ensemble = result.ensemble
    assert ensemble["copies"] == 4 and ensemble["failed"] == 0
    assert ensemble["record_factors"] == [1.0001, 0.9999, 1.0002, 0.9998]
    assert "ensemble: 4 copies" in result.report
    assert json.loads((tmp_path / "python" / "ensemble.json").read_text()) == ensemble
    single = pound.run(models / "three_span_bridge.json", histories=False)
    assert result.summary["links"] == single.summary["links"]  # the unperturbed run's
    loose = [q for q in ensemble["quantities"] if not q["robust"]]
    print(f"{len(loose)} of {len(ensemble['quantities'])} numbers not robust")
    assert all(q["spread"] > 0.05 for q in loose)
    assert not any(q["headline"] for q in loose)
    assert max(q["spread"] for q in ensemble["quantities"]) > 1e-3  # the copies differ
    assert pound.run(models / "rod_impact.json").ensemble is None


def test_an_ensemble_gives_what_pound_run_ensemble_writes(models, pound_program, tmp_path):
    result = pound.run(models / "three_span_bridge.json", ensemble=3, histories=False)
    subprocess.run([pound_program, "run", str(models / "three_span_bridge.json"), "--ensemble",
                    "3", "--out", str(tmp_path / "cli"), "-q"], check=True)
    assert json.loads((tmp_path / "cli" / "ensemble.json").read_text()) == result.ensemble


def test_ensemble_arguments_are_checked_as_the_program_checks_its_options(models):
    model = models / "two_sdof_girders.json"
    bad = {"ensemble": [dict(ensemble=0), dict(ensemble=1001), dict(ensemble=2.0),
                        dict(ensemble=10**30)],
           "perturbation": [dict(ensemble=2, perturbation=0.5), dict(ensemble=2, perturbation=0),
                            dict(ensemble=2, perturbation="1e-4"), dict(perturbation=1e-3)],
           "robust_spread": [dict(ensemble=2, robust_spread=1.0), dict(robust_spread=0.1)],
           "jobs": [dict(ensemble=2, jobs=-1), dict(jobs=2)]}
    for where, arguments in bad.items():
        for given in arguments:
            with pytest.raises(pound.InputError) as raised:
                pound.run(model, histories=False, **given)
            print(given, "->", raised.value)
            assert raised.value.path == where
    with pytest.raises(pound.InputError, match="ensemble only: add ensemble=N"):
        pound.run(model, jobs=2)


def test_an_output_folder_that_cannot_be_made_is_said_before_the_solve(models, tmp_path):
    (tmp_path / "a_file").write_text("not a folder")
    calls = []
    with pytest.raises(pound.OutputError) as raised:
        pound.run(block_on_belt(models, 0.0015), out=tmp_path / "a_file" / "out",
                  progress=lambda t, end: calls.append(t))
    print(raised.value)
    assert calls == []  # the solve never started
    with pytest.raises(pound.InputError) as raised:
        pound.run(models / "rod_impact.json", out="")
    assert raised.value.path == "out"


def test_arguments_of_the_wrong_type_are_input_errors_naming_them(models, tmp_path):
    girders = models / "two_sdof_girders.json"
    calls = {"out": lambda: pound.run(girders, out=3),
             "histories": lambda: pound.run(girders, histories="no"),
             "check": lambda: pound.run(girders, check=None),
             "perturbation": lambda: pound.run(girders, ensemble=2, perturbation=10**400),
             "time_limit": lambda: pound.run(girders, time_limit=10**400),
             "max_steps": lambda: pound.run(girders, max_steps=np.uint64(2**63)),
             "path": lambda: pound.Model.from_file(None),
             "set": lambda: pound.batch([str(girders)], tmp_path / "b"),
             "resume": lambda: pound.batch({"models": [], "records": []}, tmp_path / "c",
                                           resume="no")}
    for where, call in calls.items():
        with pytest.raises(pound.InputError) as raised:
            call()
        print(raised.value)
        assert raised.value.path == where


def test_ensemble_progress_ends_with_one_call_at_its_end(models):
    calls = []
    pound.run(models / "two_sdof_girders.json", ensemble=6, histories=False,
              progress=lambda done, runs: calls.append((done, runs)))
    print(calls)
    assert calls[-1] == (7, 7) and calls.count((7, 7)) == 1


def test_a_perturbation_that_leaves_the_records_unchanged_is_refused(models):
    with pytest.raises(pound.InputError, match="leaves the records unchanged") as raised:
        pound.run(models / "two_sdof_girders.json", ensemble=2, perturbation=1e-300)
    assert raised.value.path == "perturbation"


def test_a_missing_table_is_a_key_error_naming_the_tables(models):
    result = pound.run(models / "two_sdof_girders.json")
    with pytest.raises(KeyError, match="no table 'nope'"):
        result.units("nope")
    # A position is no name either: the same message, not a bare KeyError(3).
    with pytest.raises(KeyError, match="no table 3: the tables are"):
        result.to_pandas(3)


def test_sigterm_ends_python_as_it_would_without_pound(models, signalled):
    done = signalled(f"""
try:
    pound.run(pound.Model.from_file({str(models / "block_on_belt.json")!r}), max_steps=0)
except KeyboardInterrupt:
    print("survived SIGTERM as a KeyboardInterrupt")
""", "SIGTERM")
    assert done.returncode == -signal.SIGTERM and "survived" not in done.stdout


def test_a_handler_of_the_script_runs_and_what_it_raises_is_raised(models, signalled):
    # SIGINT and SIGTERM reach the script's own handlers, as they would without pound.
    for name in ("SIGINT", "SIGTERM"):
        done = signalled(f"""
class Stop(Exception):
    pass
def stop(number, frame):
    raise Stop(signal.Signals(number).name)
signal.signal(signal.{name}, stop)
try:
    pound.run(pound.Model.from_file({str(models / "block_on_belt.json")!r}), max_steps=0)
except Stop as raised:
    print("raised", raised, "after", round(time.monotonic() - start, 2))
""", name)
        assert done.returncode == 0 and f"raised {name} after" in done.stdout
        assert float(done.stdout.split("after")[1].split()[0]) < 2.0


def test_a_handler_that_returns_leaves_the_run_interrupted(models, signalled):
    # A handler that only takes note (a graceful shutdown's flag): the run cannot go on from
    # where it stopped, and says so as an interrupted system call does.
    for name in ("SIGINT", "SIGTERM"):
        done = signalled(f"""
noted = []
signal.signal(signal.{name}, lambda number, frame: noted.append(number))
try:
    pound.run(pound.Model.from_file({str(models / "block_on_belt.json")!r}), max_steps=0)
except InterruptedError as stopped:
    print("noted", len(noted), "|", stopped)
""", name)
        assert done.returncode == 0 and "noted 1 |" in done.stdout
        assert f"stopped by {name}: the script's handler returned" in done.stdout


def test_results_and_errors_cross_to_a_process_pool(models, tmp_path):
    # A study spread over a process pool gets each worker's Result whole, and a bad model's
    # InputError as the worker raised it (an exception that cannot be rebuilt from its args
    # reached the parent as a TypeError about pickling).
    import concurrent.futures
    import pickle
    bad = tmp_path / "bad.json"
    bad.write_text('{"nodes": 3}')
    with concurrent.futures.ProcessPoolExecutor(2) as pool:
        remote = pool.submit(pound.run, models / "two_sdof_girders.json").result()
        with pytest.raises(pound.InputError) as raised:
            pool.submit(pound.run, bad).result()
    assert raised.value.file == str(bad) and raised.value.path == "/nodes"
    local = pound.run(models / "two_sdof_girders.json")
    assert remote.summary.pop("run_time_s") > 0 and local.summary.pop("run_time_s") > 0
    assert remote.summary == local.summary and remote.warnings == local.warnings
    assert remote.to_pandas().equals(local.to_pandas())
    loaded = pickle.loads(pickle.dumps(local))
    assert (loaded.summary, loaded.report, repr(loaded)) == (local.summary, local.report,
                                                             repr(local))
    for item, quantities in local.links.items():
        for quantity, values in quantities.items():
            assert np.array_equal(remote.links[item][quantity], values)
            assert not remote.links[item][quantity].flags.writeable
            assert np.array_equal(loaded.links[item][quantity], values)
    with pytest.raises(pound.AnalysisError) as stopped:
        pound.run(models / "two_sdof_girders.json", max_steps=5)
    again = pickle.loads(pickle.dumps(stopped.value))
    assert (again.time, again.reason, str(again)) == (stopped.value.time, stopped.value.reason,
                                                      str(stopped.value))
    assert again.result.summary == stopped.value.result.summary
