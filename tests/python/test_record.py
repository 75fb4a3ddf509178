"""pound.Record: files, arrays, spectra against closed forms, and bad samples."""

import math

import numpy as np
import pytest

import pound


def test_an_at2_file_is_read_in_g_with_its_time_step(repository, pound_program):
    import json
    import subprocess
    path = repository / "ground_motions" / "synthetic_firm_01.AT2"
    record = pound.Record.from_file(path)
    printed = json.loads(subprocess.run([pound_program, "spectrum", str(path), "--json"],
                                        capture_output=True, text=True, check=True).stdout)
    print(record, f"peak {record.peak:.6g} g")
    assert record.format == "at2" and len(record.sha1) == 40
    assert record.time_step == printed["dt"]
    assert record.peak == pytest.approx(printed["pga_g"], rel=1e-12)
    assert len(record.times) == len(record.accelerations) == printed["npts"]
    assert not record.accelerations.flags.writeable


def test_the_real_records_of_shared_are_read(shared_records):
    records = sorted(shared_records.glob("*.AT2"))
    assert records
    for path in records:
        record = pound.Record.from_file(path)
        assert 0.0 < record.peak < 5.0 and record.time_step > 0.0, path


def step_response(a0, period, damping, times):
    """u(t) of a linear oscillator from rest under a constant ground acceleration a0."""
    omega = 2 * math.pi / period
    damped = omega * math.sqrt(1 - damping ** 2)
    decay = np.exp(-damping * omega * times)
    return -(a0 / omega ** 2) * (1 - decay * (np.cos(damped * times) + damping * omega / damped
                                              * np.sin(damped * times)))


@pytest.mark.parametrize("damping", [0.0, 0.05, 0.2])
def test_a_step_of_ground_acceleration_has_the_closed_form_spectrum(damping):
    # The recurrence is exact at the samples for a piecewise-linear record, and the spectrum takes
    # the peak at the samples: Sa = w^2 max_k |u(t_k)| of the closed form.
    a0, dt = 0.3, 0.01
    record = pound.Record(dt, np.full(1001, a0))
    periods = np.array([0.2, 0.37, 1.0, 2.0])
    sa = record.spectrum(periods, damping)["sa"]
    times = np.arange(1001) * dt
    exact = np.array([(2 * math.pi / T) ** 2 * np.max(np.abs(step_response(a0, T, damping,
                                                                           times)))
                      for T in periods])
    error = np.max(np.abs(sa - exact) / exact)
    print(f"damping {damping}: Sa {sa}, largest relative error {error:.2e}")
    assert error < 1e-9
    # Between the samples the true peak a0 (1 + exp(-pi z / sqrt(1 - z^2))) is at most a
    # sampling error above.
    peak = a0 * (1 + math.exp(-math.pi * damping / math.sqrt(1 - damping ** 2)))
    assert np.all(sa <= peak * (1 + 1e-12)) and np.all(sa > 0.99 * peak)


def test_period_zero_gives_the_peak_and_scale_scales():
    record = pound.Record(0.02, [0.0, 0.1, -0.25, 0.05], "m/s2", scale=2.0)
    assert record.peak == pytest.approx(0.5)
    assert record.spectrum([0.0])["sa"][0] == pytest.approx(0.5)
    assert len(record.spectrum()["periods"]) == 40


def test_times_give_the_step_and_must_be_uniform():
    assert pound.Record(np.arange(5) * 0.005 + 3.0, np.zeros(5)).time_step == pytest.approx(0.005)
    with pytest.raises(pound.InputError) as raised:
        pound.Record([0.0, 0.01, 0.02, 0.05, 0.06], np.zeros(5), name="uneven")
    print(raised.value)
    assert raised.value.file == "uneven" and raised.value.path == "times[3]"


@pytest.mark.parametrize("times_or_dt, accelerations, path", [
    (0.01, [0.0, np.nan, 0.1], "accelerations[1]"),
    (0.01, [0.0, 0.1, np.inf], "accelerations[2]"),
    (0.01, [0.1], "accelerations"),
    (0.0, [0.0, 0.1], "time_step"),
    (-0.01, [0.0, 0.1], "time_step"),
    ([0.0, 0.01], [0.0, 0.1, 0.2], "times"),
    (0.01, [[0.0, 0.1], [0.2, 0.3]], "accelerations"),
    (0.01, ["a", "b"], "accelerations"),
])
def test_bad_samples_raise_input_error_naming_them(times_or_dt, accelerations, path):
    with pytest.raises(pound.InputError) as raised:
        pound.Record(times_or_dt, accelerations)
    print(raised.value)
    assert raised.value.path == path


def test_periods_beyond_any_structures_are_refused(repository):
    record = pound.Record.from_file(repository / "ground_motions" / "synthetic_firm_01.AT2")
    assert record.spectrum([1000.0])["sa"][0] > 0.0
    with pytest.raises(pound.InputError) as raised:
        record.spectrum([1.0, 1e308])
    assert raised.value.path == "periods[1]"
    assert "in [0, 1000] of the record's unit of time (1000 s)" in raised.value.message


def test_a_record_in_milliseconds_takes_its_periods_in_milliseconds(repository):
    # The same samples with their step in ms (time_unit="ms"): the default periods are the same
    # 0.02 to 10 s, given in ms, and so are the spectra; periods up to 1000 s (1e6 ms) are
    # taken. Without time_unit a step of 10 read the defaults as 0.02 to 10 ms, a spectrum flat
    # at the PGA, and refused 2000 ms as past "1000 s" (audit 71).
    in_seconds = pound.Record.from_file(repository / "ground_motions" / "synthetic_firm_01.AT2")
    in_ms = pound.Record(1000.0 * in_seconds.time_step, in_seconds.accelerations, time_unit="ms")
    print(in_ms)
    seconds, milliseconds = in_seconds.spectrum(), in_ms.spectrum()
    assert np.allclose(milliseconds["periods"], 1000.0 * seconds["periods"], rtol=1e-15)
    assert np.allclose(milliseconds["sa"], seconds["sa"], rtol=1e-12)
    assert in_ms.spectrum([2000.0])["sa"][0] == pytest.approx(in_seconds.spectrum([2.0])["sa"][0],
                                                              rel=1e-12)
    assert "dt = 10 ms" in repr(in_ms) and "dt = 0.01 s" in repr(in_seconds)
    pair = in_ms.pair_spectrum(in_ms, [500.0])
    assert pair["rotd50"][0] == pytest.approx(in_seconds.spectrum([0.5])["sa"][0], rel=1e-12)
    with pytest.raises(pound.InputError) as raised:
        pound.Record(0.01, [0.0, 0.1], time_unit="min")
    assert raised.value.path == "time_unit"


def test_bad_units_scale_and_files_are_refused(tmp_path):
    with pytest.raises(ValueError, match="unknown acceleration unit"):
        pound.Record(0.01, [0.0, 0.1], "furlongs")
    with pytest.raises(pound.InputError, match="scale"):
        pound.Record(0.01, [0.0, 0.1], scale=-1.0)
    with pytest.raises(pound.InputError) as raised:
        pound.Record.from_file(tmp_path / "none.AT2")
    assert "none.AT2" in raised.value.file
    (tmp_path / "short.txt").write_text("0.1\n0.2\n")
    with pytest.raises(pound.InputError) as raised:
        pound.Record.from_file(tmp_path / "short.txt")
    print(raised.value)
    assert raised.value.file.endswith("short.txt")


def test_a_pair_gives_the_measures_of_pound_spectrum_pair(repository, pound_program):
    import json
    import subprocess
    firm = repository / "ground_motions" / "synthetic_firm_01.AT2"
    soft = repository / "ground_motions" / "synthetic_soft_01.AT2"
    first, second = pound.Record.from_file(firm), pound.Record.from_file(soft)
    periods = [0.0, 0.2, 1.0]
    pair = first.pair_spectrum(second, periods, rotation=20.0)
    printed = json.loads(subprocess.run(
        [pound_program, "spectrum", str(firm), "--pair", str(soft), "--rotation", "20",
         "--periods", "0,0.2,1", "--json"], capture_output=True, text=True, check=True).stdout)
    print({key: value for key, value in pair.items()})
    for key, printed_key in [("sa1", "sa1_g"), ("sa2", "sa2_g"), ("rotd50", "rotd50_g"),
                             ("rotd100", "rotd100_g"), ("geometric_mean", "geometric_mean_g")]:
        # The program reads in m/s^2 and prints g; the module keeps the records' g.
        assert np.allclose(pair[key], printed[printed_key], rtol=1e-13, atol=0), key
    assert list(pair["rotd100_angle"]) == printed["rotd100_angle_deg"]
    # Turning the sensors moves the components' Sa, not RotD50.
    plain = first.pair_spectrum(second, periods)
    assert not np.allclose(plain["sa1"], pair["sa1"])
    assert np.allclose(plain["rotd50"], pair["rotd50"], rtol=1e-12, atol=0)


def test_a_pair_on_different_grids_or_units_is_refused():
    first = pound.Record(0.01, np.sin(np.arange(100) * 0.1))
    with pytest.raises(pound.InputError, match="as many samples") as error:
        first.pair_spectrum(pound.Record(0.01, np.zeros(99), name="east"))
    assert error.value.file == "east"
    with pytest.raises(pound.InputError, match="one time step"):
        first.pair_spectrum(pound.Record(0.02, np.zeros(100)))
    with pytest.raises(pound.InputError, match="in one unit"):
        first.pair_spectrum(pound.Record(0.01, np.zeros(100), "m/s2"))
    with pytest.raises(pound.InputError, match="expected a pound.Record"):
        first.pair_spectrum(np.zeros(100))
    with pytest.raises(pound.InputError, match="finite angle"):
        first.pair_spectrum(pound.Record(0.01, np.zeros(100)), rotation=float("nan"))


def test_complex_boolean_and_text_samples_are_refused():
    # NumPy would drop an imaginary part (with a warning), read True as 1 and parse "0.1".
    for values in (np.array([0.0, 0.1 + 0.2j]), np.array([True, False]), ["0.0", "0.1"]):
        with pytest.raises(pound.InputError, match="no real number") as raised:
            pound.Record(0.01, values)
        assert raised.value.path == "accelerations"
    with pytest.raises(pound.InputError, match="no real number") as raised:
        pound.Record(np.array([0.0, 0.01 + 0j]), [0.0, 0.1])
    assert raised.value.path == "times"
    assert pound.Record(0.01, np.array([0, 1], dtype=np.int32)).time_step == 0.01
