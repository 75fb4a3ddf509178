"""Every argument of the public functions, given a value of the wrong type or out of range, ends
in an InputError naming it (or, where the value is acceptable, a result): never a TypeError,
ValueError or OverflowError from the binding, a crash, or a hang. The values are those a user's
typo or a NumPy pipeline gives."""

import math

import numpy as np

import pound

BAD_VALUES = [None, "", "abc", -1, 0, 3.5, math.nan, math.inf, -math.inf, 10**400, True, [],
              {}, object(), np.float64("nan"), np.int64(-5), np.uint64(2**63), b"bytes"]


def calls(models, record_path):
    """(name, argument, call taking the argument's value): each call is valid with a good value."""
    girders = models / "two_sdof_girders.json"
    model = pound.Model.from_file(girders)
    takeda = pound.Model.from_file(models / "three_span_bridge_takeda.json")
    record = pound.Record.from_file(record_path)
    samples = np.sin(np.arange(200) / 10.0) * 0.1
    fast = {"histories": False}
    return [
        ("run", "record", lambda v: pound.run(girders, v, **fast)),
        ("run", "out", lambda v: pound.run(girders, out=v, **fast)),
        ("run", "max_steps", lambda v: pound.run(girders, max_steps=v, check=False, **fast)),
        ("run", "time_limit", lambda v: pound.run(girders, time_limit=v, **fast)),
        ("run", "histories", lambda v: pound.run(girders, histories=v)),
        ("run", "check", lambda v: pound.run(girders, check=v, **fast)),
        ("run", "progress", lambda v: pound.run(girders, progress=v, **fast)),
        ("run", "ensemble", lambda v: pound.run(girders, ensemble=v, **fast)),
        ("run", "perturbation", lambda v: pound.run(girders, ensemble=2, perturbation=v, **fast)),
        ("run", "robust_spread", lambda v: pound.run(girders, ensemble=2, robust_spread=v,
                                                     **fast)),
        ("run", "jobs", lambda v: pound.run(girders, ensemble=2, jobs=v, **fast)),
        ("batch", "set", lambda v: pound.batch(v, "batch_out")),
        ("batch", "out", lambda v: pound.batch({"models": [str(girders)], "records": []}, v)),
        ("batch", "jobs", lambda v: pound.batch({"models": [], "records": []}, "b2", jobs=v)),
        ("batch", "resume", lambda v: pound.batch({"models": [], "records": []}, "b3", resume=v)),
        ("batch", "progress", lambda v: pound.batch({"models": [], "records": []}, "b4",
                                                    progress=v)),
        ("Model.from_file", "path", lambda v: pound.Model.from_file(v)),
        ("Model.from_dict", "model", lambda v: pound.Model.from_dict(v)),
        ("Model.from_dict", "name", lambda v: pound.Model.from_dict(model.to_dict(), name=v)),
        ("Model.from_dict", "folder", lambda v: pound.Model.from_dict(model.to_dict(), folder=v)),
        ("modes", "count", lambda v: model.modes(v)),
        ("pushover", "node", lambda v: takeda.pushover(v, 0.01, increments=2)),
        ("pushover", "to", lambda v: takeda.pushover("bridge.p1.top", v, increments=2)),
        ("pushover", "direction", lambda v: takeda.pushover("bridge.p1.top", 0.01, direction=v,
                                                            increments=2)),
        ("pushover", "pattern", lambda v: takeda.pushover("bridge.p1.top", 0.01, pattern=v,
                                                          increments=2)),
        ("pushover", "increments", lambda v: takeda.pushover("bridge.p1.top", 0.01,
                                                             increments=v)),
        ("pushover", "out", lambda v: takeda.pushover("bridge.p1.top", 0.01, increments=2, out=v)),
        ("pushover", "check", lambda v: takeda.pushover("bridge.p1.top", 0.01, increments=2,
                                                        check=v)),
        ("Record", "times_or_dt", lambda v: pound.Record(v, samples)),
        ("Record", "accelerations", lambda v: pound.Record(0.01, v)),
        ("Record", "units", lambda v: pound.Record(0.01, samples, v)),
        ("Record", "name", lambda v: pound.Record(0.01, samples, name=v)),
        ("Record", "scale", lambda v: pound.Record(0.01, samples, scale=v)),
        ("Record.from_file", "path", lambda v: pound.Record.from_file(v)),
        ("Record.from_file", "units", lambda v: pound.Record.from_file(record_path, v)),
        ("Record.from_file", "column", lambda v: pound.Record.from_file(record_path, column=v)),
        ("Record.from_file", "scale", lambda v: pound.Record.from_file(record_path, scale=v)),
        ("Record.from_file", "dt", lambda v: pound.Record.from_file(record_path, dt=v)),
        ("Record.from_file", "time_column", lambda v: pound.Record.from_file(record_path,
                                                                            time_column=v)),
        ("Record.from_file", "format", lambda v: pound.Record.from_file(record_path, format=v)),
        ("spectrum", "periods", lambda v: record.spectrum(v)),
        ("spectrum", "damping", lambda v: record.spectrum(damping=v)),
        ("pair_spectrum", "second", lambda v: record.pair_spectrum(v)),
        ("pair_spectrum", "periods", lambda v: record.pair_spectrum(record, v)),
        ("pair_spectrum", "damping", lambda v: record.pair_spectrum(record, damping=v)),
        ("pair_spectrum", "rotation", lambda v: record.pair_spectrum(record, rotation=v)),
        ("verify.rod_impact", "n", lambda v: pound.verify.rod_impact(n=v, duration_ratio=0.5)),
        ("verify.rod_impact", "k_ratio", lambda v: pound.verify.rod_impact(n=10, k_ratio=v)),
        ("verify.rod_impact", "law", lambda v: pound.verify.rod_impact(n=10, law=v)),
    ]


def test_every_argument_refuses_a_bad_value_naming_itself(models, repository, tmp_path,
                                                         monkeypatch):
    monkeypatch.chdir(tmp_path)  # outputs named by the bad values land here
    record_path = repository / "ground_motions" / "synthetic_firm_01.AT2"
    broken, accepted = [], []
    refused = 0
    for function, argument, call in calls(models, record_path):
        for value in BAD_VALUES:
            try:
                call(value)
                accepted.append(f"{function}({argument}={value!r})")
            except pound.InputError:
                refused += 1
            except pound.AnalysisError:  # a run the value let start, failing loudly (max_steps=1)
                accepted.append(f"{function}({argument}={value!r}): AnalysisError")
            except Exception as error:  # noqa: BLE001 - the contract is what is caught
                broken.append(f"{function}({argument}={value!r}): {type(error).__name__}: "
                              f"{error}")
    print(f"{refused} refused, {len(accepted)} accepted, {len(broken)} broken")
    print("accepted:", "; ".join(accepted))
    print("\n".join(broken))
    assert not broken
