"""Fixtures of the Python module's tests: the repository, the `pound` program to compare with."""

import os
import pathlib
import shutil
import subprocess
import sys

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture
def repository():
    return REPOSITORY


@pytest.fixture
def models():
    return REPOSITORY / "models"


@pytest.fixture
def pound_program():
    """The `pound` program of the same build (ctest sets POUND_PROGRAM)."""
    program = os.environ.get("POUND_PROGRAM") or shutil.which("pound")
    if not program:
        pytest.skip("POUND_PROGRAM is not set and no pound on PATH: nothing to compare with")
    return program


@pytest.fixture
def shared_records():
    folder = REPOSITORY.parent / "shared" / "ground_motions"
    if not folder.is_dir():
        pytest.skip("../shared/ground_motions is absent (a clone on its own)")
    return folder


@pytest.fixture
def signalled():
    """Runs `script` (code using `pound`, `start` its start time) in a fresh interpreter that sends
    itself `signal_name` after 0.5 s; returns the finished process. The module is this build's."""
    module = pathlib.Path(__import__("pound").__file__).parents[1]

    def run(script, signal_name="SIGINT"):
        prelude = (f"import json, os, signal, sys, threading, time\n"
                   f"sys.path.insert(0, {str(module)!r})\nimport pound\nthreading.Timer(0.5, lambda: os.kill(os.getpid(), "
                   f"signal.{signal_name})).start()\nstart = time.monotonic()\n")
        done = subprocess.run([sys.executable, "-c", prelude + script], capture_output=True,
                              text=True, timeout=120)
        print(done.returncode, done.stdout, done.stderr)
        return done

    return run
