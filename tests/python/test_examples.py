"""The examples of examples/python run (on small sweeps) and draw their figures."""

import pathlib
import subprocess
import sys

import pytest

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python"


def run_example(name, *arguments):
    pytest.importorskip("matplotlib")
    done = subprocess.run([sys.executable, str(EXAMPLES / name), *arguments],
                          capture_output=True, text=True, timeout=300)
    print(done.stdout, done.stderr)
    assert done.returncode == 0


def test_the_gap_sweep_plots_force_and_drift_against_gap(tmp_path):
    run_example("gap_sweep.py", "--out", str(tmp_path), "--gaps", "0,3,12", "--jobs", "2")
    rows = (tmp_path / "gap_sweep.csv").read_text().splitlines()
    assert len(rows) == 1 + 3 * 4
    assert (tmp_path / "gap_sweep.png").stat().st_size > 10000
    # Far enough apart, the buildings never touch under the firm-ground records.
    wide = [row.split(",") for row in rows[1:] if float(row.split(",")[0]) == 0.12]
    assert any(float(row[2]) == 0.0 for row in wide)


def test_the_ida_fits_a_fragility(tmp_path):
    run_example("ida_fragility.py", "--out", str(tmp_path / "ida"), "--scales", "0.5,1,2",
                "--jobs", "2")
    assert (tmp_path / "ida" / "ida_fragility.png").stat().st_size > 10000
    assert (tmp_path / "ida" / "batch_summary.csv").read_text().count("\n") == 1 + 12
